# hal_parport and serport against the devices qemu emulates: a parallel port at 0x378
# and a second 16550 at 0x2f8 that Linux leaves alone (qemu -parallel null -serial
# mon:stdio -serial null, kernel 8250.nr_uarts=1; parport_pc is not loaded).
# NOT YET RUN: with those options in run-kernel-tests.sh the VM printed nothing after
# "Booting from ROM" for 7 minutes (issue 13 session; cause not found: the next step
# is a boot with loglevel=8 to see where it stops). Once the VM boots with the devices,
# move this file to cases/40-qemu-ports.sh. The tests live with their
# components (tests/hal_parport/qemu-lpt, tests/serport/qemu-uart) but need those
# devices and, for the UART's loopback mode, /dev/port: they run here, as root, not in
# the HAL suite (skip-flavor-* there).
export HAL_FLAVOR=kernel HAL_TEST_FLAVOR=kernel
fail=0
run() {	# DIR: test.sh, then checkresult or expected, as the HAL suite does
	out=/tmp/qemu-ports.result
	rc=0 ok=0	# (this runs under sh -e: failures are caught, not fatal)
	(cd "$1" && timeout 120 sh test.sh) >"$out" 2>&1 </dev/null || rc=$?
	timeout 30 halrun -U >/dev/null 2>&1 </dev/null || true
	if [ $rc -ne 0 ]; then
		ok=1
	elif [ -x "$1/checkresult" ]; then
		(cd "$1" && ./checkresult "$out") || ok=1
	else
		diff -u "$1/expected" "$out" || ok=1
	fi
	if [ $ok -eq 0 ]; then
		echo "QEMU-PORTS PASS $1"
	else
		echo "FAILED: $1 (exit $rc)"; sed 's/^/| /' "$out"; fail=1
	fi
}
grep -E 'parport|serial|0378|02f8' /proc/ioports | sed 's/^/ioports: /'
run /tests/hal/hal_parport/qemu-lpt
run /tests/hal/serport/qemu-uart
[ $fail -eq 0 ]
