# STATE ESTOP and STATE OFF are done when the status shows them: a status read right
# after the command sees ESTOP / ESTOP_RESET (emcrsh's GET ESTOP after SET ESTOP ON).
# ESTOP latches in task as EMC2's iocontrol latched it: with emc-enable-in held TRUE
# (no loop wired) the machine still goes to ESTOP and stays there, with
# user-enable-out FALSE, until ESTOP_RESET.
. ../lib.sh
task_start held.hal
for round in 1 2 3; do
	bus state estop_reset || exit 1
	bus state on || exit 1
	bus status task.state
	bus state off || exit 1
	bus status task.state traj.enabled
	bus state on || exit 1
	bus state estop || exit 1
	bus status task.state traj.enabled
done
sleep 0.3
bus status task.state
echo "user-enable-out $(halcmd getp iocontrol.0.user-enable-out)"
bus state estop_reset || exit 1
bus status task.state
task_stop
