# halmeter with no HAL session running: one line saying so, exit 1, and nothing made
# (no HAL segment in /dev/shm in the simulated flavor, hal_lib.ko not loaded in the
# kernel flavor) that the next session would find.
made() {
	if [ "$HAL_TEST_FLAVOR" = kernel ]; then
		grep -c '^hal_lib ' /proc/modules
	else
		ls /dev/shm | grep -c -- "-${RTAPI_INSTANCE:-0}-"
	fi
}
echo "before: $(made)"
halmeter -t -n 1 pin nosuch.pin 2>&1 | sed 's/ (.*)//'
echo "exit $(halmeter -t -n 1 pin nosuch.pin >/dev/null 2>&1; echo $?)"
halmeter -t -n 1 sig x 2>/dev/null
echo "after: $(made)"
# with a session, the same command finds the HAL (and the pin is what is missing)
halcmd loadrt not
halmeter -t -n 1 pin nosuch.pin 2>&1
echo "exit $?"
halmeter -t -n 1 pin not.0.out
halrun -U
echo "after halrun -U: $(made)"
