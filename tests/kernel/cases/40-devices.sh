# The tests that drive devices (the HAL tests with a needs-devices file), as root:
# hal_parport and serport against the parallel port and the second 16550 that qemu
# emulates (run-kernel-tests.sh: -parallel null -serial mon:stdio -serial null, an LPT
# at 0x378 and COM2 at 0x2f8), hal_input on uinput devices and shuttlexpress on a uhid
# device (tests/helpers/hal_testdev.cpp). The HAL suite (10-hal-suite.sh) runs as a
# 'hal' member, which may not write /dev/port, /dev/uinput or /dev/uhid, and skips them.
#
# Linux must leave the ports alone: parport_pc is not loaded (nothing claims 0x378),
# and the 8250 driver, which claims every 16550 it finds, is unbound from COM2 here.
# (Not 8250.nr_uarts=1: with a single slot, the 8250 PnP probe, which sees COM2 first,
# moves ttyS0 and with it the kernel console to 0x2f8, qemu's null device, and the VM
# runs on with no output.)
for d in /sys/bus/pnp/devices/*; do
	if grep -q 'io 0x2f8-0x2ff' "$d/resources" && [ -e "$d/driver" ]; then
		echo "${d##*/}" >"$d/driver/unbind"
	fi
done
# evdev (event nodes), uinput, and hid + uhid + hid-generic (hidraw nodes) from the
# kernel's own modules (run-kernel-tests.sh copies them to /lib/testdev-modules)
for m in evdev uinput hid uhid hid-generic; do
	grep -q "^$(echo $m | tr - _) " /proc/modules || insmod "/lib/testdev-modules/$m.ko"
done
grep -E 'parport|serial|0378|02f8' /proc/ioports | sed 's/^ */ioports: /'
rc=0
HAL_TEST_DEVICES_ONLY=1 sh /tests/run-hal-tests-vm.sh /tests/hal || rc=$?
for m in hid_generic uhid hid uinput evdev; do rmmod $m 2>/dev/null || true; done
exit $rc
