# [HALUI]MDI_COMMAND lines run from halui.mdi-command-NN: from MANUAL (halui switches
# to MDI, runs the line, returns to MANUAL once task reports it done), from AUTO
# (back to AUTO) and from MDI (stays). While a slow command runs halui's pins keep
# updating (the loop does not wait for the command).
. ../lib.sh
machine_start
machine_on
echo "manual: $(bus status task.mode)"
press mdi-command-00
bus wait traj.position "12.000000 -3.000000 0.000000" 10 || exit 1
bus wait task.mode MANUAL 5 || exit 1
echo "after mdi-command-00: $(bus status traj.position) $(bus status task.mode)"
halcmd setp halui.mdi-command-01 1 || exit 1
# G1 Z-4 at 120 mm/min takes 2 s: the Z pin moves meanwhile
n=0
moving=no
while [ $n -lt 100 ]; do
	z=$(pin axis.z.pos-commanded)
	if awk -v z="$z" 'BEGIN { exit !(z < -0.2 && z > -3.8) }'; then
		moving=yes
		break
	fi
	n=$((n + 1))
	sleep 0.05
done
echo "axis.z.pos-commanded moves while the command runs: $moving (mode $(bus status task.mode))"
halcmd setp halui.mdi-command-01 0 || exit 1
bus wait traj.position "12.000000 -3.000000 -4.000000" 10 || exit 1
bus wait task.mode MANUAL 5 || exit 1
wait_pin mode.is-manual TRUE
echo "after mdi-command-01: $(bus status traj.position) $(bus status task.mode)"
press mode.auto
bus wait task.mode AUTO 5 || exit 1
press mdi-command-00
bus wait traj.position "12.000000 -3.000000 0.000000" 10 || exit 1
bus wait task.mode AUTO 5 || exit 1
echo "from auto: back in $(bus status task.mode)"
press mode.mdi
bus wait task.mode MDI 5 || exit 1
press mdi-command-01
bus wait traj.position "12.000000 -3.000000 -4.000000" 10 || exit 1
sleep 0.2
echo "from mdi: stays in $(bus status task.mode)"
joints
machine_stop
