# MDI moves reach the joints: G0 and G1 in MDI mode end at their targets; the
# commanded position in task's status follows.
. ../lib.sh
task_start
machine_ready
bus mdi G0 X10 Y5 || exit 1
joints
bus mdi G1 X20 Y-5 Z-2 F600 || exit 1
joints
bus status traj.position task.state task.mode task.interp
task_stop
