# The demo's emcrsh drive step (demo/drive-emcrsh.sh) when task refuses: a program
# file that does not exist (SET OPEN NAK, with GET ERROR's text) and a program that
# stops on an error line (PROGRAM_STATUS IDLE with GET ERROR's text). Each time
# demo/mill-run.sh exits 1 naming the step, after the launcher's full clean-up, and
# no emcrsh is left running.
T=${TEST_TMPDIR:-/tmp}
printf 'G21 G90\nG0 X1\nG1 X2 F100\nG1 X3 Q\nM2\n' > "$T/bad.ngc"
for prog in "$T/missing.ngc" "$T/bad.ngc"; do
	DEMO_PROGRAM=$prog ../../../demo/mill-run.sh "$T/run" > "$T/out" 2>&1
	echo "exit $?"
	sed "s|$T/||g" "$T/out"
	[ -e "$T/run/emc.lock" ] && echo "lock file left" || echo "no lock file left"
	if [ "$HAL_TEST_FLAVOR" = kernel ]; then
		echo "left $(grep -c '^hal_lib ' /proc/modules)"
	else
		echo "left $(ls /dev/shm | grep -c -- "-${RTAPI_INSTANCE:-0}-")"
	fi
	echo "emcrsh left $(ps -o args= -e | grep -c "^emcrsh .*$T/run/cfg/mill.ini")"
done
