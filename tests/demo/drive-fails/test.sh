# A failing drive step (DEMO_DRIVE, here one whose homing fails) stops demo/mill-run.sh
# with exit 1 and a message naming the step, after the launcher's full clean-up:
# no lock file, no shared memory (sim) or hal_lib module (kernel) left.
T=${TEST_TMPDIR:-/tmp}
cat > "$T/drive.sh" <<'SH'
#!/bin/sh
echo "drive: $1 refused (test)" >&2
exit 1
SH
chmod +x "$T/drive.sh"
DEMO_DRIVE=$T/drive.sh ../../../demo/mill-run.sh "$T/run" 2>&1
echo "exit $?"
[ -e "$T/run/emc.lock" ] && echo "lock file left" || echo "no lock file left"
if [ "$HAL_TEST_FLAVOR" = kernel ]; then
	echo "left $(grep -c '^hal_lib ' /proc/modules)"
else
	echo "left $(ls /dev/shm | grep -c -- "-${RTAPI_INSTANCE:-0}-")"
fi
