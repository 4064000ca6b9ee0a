# An estop reset sent before iocontrol has connected waits for it (task's start-up
# window); once io has been gone for longer than that window, a reset is refused.
. ../lib.sh
halcmd setexact_for_test_suite_only || exit 1
halcmd -f ../common/machine.hal || exit 1
halcmd start || exit 1
halcmd loadusr -Wn inihal milltask -ini "$INI" -bus "$BUS" || exit 1
bus wait task.motion_ready 1 10 || exit 1
bus status io.connected
echo "-- reset sent first, io started 1 s later"
bus state estop_reset > "$T/reset.out" 2>&1 &
reset=$!
sleep 1
halcmd loadusr -Wn iocontrol io -ini "$INI" -bus "$BUS" || exit 1
halcmd net estop-loop iocontrol.0.user-enable-out iocontrol.0.emc-enable-in || exit 1
wait $reset
echo "reset exit $?"
cat "$T/reset.out"
bus state on || exit 1
bus status task.state
echo "-- io gone: estop, and after the window a reset is refused"
halcmd unloadusr iocontrol || exit 1
bus wait task.state ESTOP 5 || exit 1
bus status task.state
sleep 5.5
bus state estop_reset
echo "reset exit $?"
halcmd unloadusr inihal
halrun -U
