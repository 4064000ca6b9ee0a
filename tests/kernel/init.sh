#!/bin/busybox sh
# init.sh - /init of the kernel-test VM: mounts the basics, runs every case under
# /tests/cases in order and powers off. Each case prints its own lines; this prints
#   KTEST <case> PASS|FAIL
# per case and "KTEST-DONE <passed> <failed>" last, which the host script parses.
/bin/busybox --install -s /bin
mount -t proc proc /proc
mount -t sysfs sysfs /sys
mount -t devtmpfs devtmpfs /dev
# pseudo-terminals: gs2_vfd's test puts its simulated drive on one
mkdir -p /dev/pts && mount -t devpts -o mode=620,ptmxmode=666 devpts /dev/pts
export PATH=/bin:/sbin:/tests PATH_MOD=/lib/hal/modules/$(uname -r)
# Users as docs/kernel-security.md describes them (accounts made by run-kernel-tests.sh):
# group 'hal' (gid 990) with user 'haluser' (uid 1000) in it, 'nobody' (65534) outside
# it; the helper 4750 root:hal, and /dev/rtapi 0660 root:hal as
# firmware/udev/60-hal.rules says for udev.
mkdir -p /home/haluser
# (No udevd here, and Debian's kernels have no uevent helper: this loop applies the
# rule whenever rtapi.ko creates the node; halcmd waits up to 2 s for the group.)
(while :; do
	[ -c /dev/rtapi ] && [ "$(stat -c %g:%a /dev/rtapi)" != 990:660 ] &&
		chown 0:990 /dev/rtapi && chmod 660 /dev/rtapi
	sleep 0.1
done) &
chown 0:990 /bin/emc_module_helper && chmod 4750 /bin/emc_module_helper
chmod 1777 /tmp
# the loopback interface (down at boot): emcrsh's tests talk TCP on 127.0.0.1
ip link set lo up 2>/dev/null || ifconfig lo 127.0.0.1 up
# The kernel's firmware search path gets a directory every test may write: drivers
# that upload FPGA images (pluto_servo, pluto_step) read test-made dummies from there
# (tests/helpers/pluto-firmware.sh).
mkdir -p /tmp/hal-firmware && chmod 1777 /tmp/hal-firmware
printf /tmp/hal-firmware >/sys/module/firmware_class/parameters/path
chown -R 1000:1000 /home/haluser /tests/hal
echo
pass=0 fail=0
for t in /tests/cases/*.sh; do
	name=${t##*/}; name=${name%.sh}
	echo "KTEST-BEGIN $name"
	t0=$(cut -d. -f1 /proc/uptime)
	if sh -e "$t"; then
		res=PASS; pass=$((pass + 1))
	else
		res=FAIL; fail=$((fail + 1))
	fi
	echo "KTEST $name $res ($(($(cut -d. -f1 /proc/uptime) - t0)) s)"
	# leave a clean kernel for the next case whatever this one did (functions still on
	# a thread hold their modules: halrun -U takes them off first)
	[ -e /proc/rtapi ] && HAL_FLAVOR=kernel halrun -U >/dev/null 2>&1
	for m in $(lsmod | awk 'NR > 1 && $1 != "rtapi" && $1 != "hal_lib" { print $1 }'); do rmmod "$m"; done
	rmmod hal_lib 2>/dev/null; rmmod rtapi 2>/dev/null
done
echo "KTEST-DONE $pass $fail"
poweroff -f
