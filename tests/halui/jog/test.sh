# Jogs through halui: a continuous joint jog (plus held, then released: it stops), an
# analog joint jog, incremental joint jogs by number and through the selected joint,
# then in teleop incremental and continuous axis jogs, the selected axis, and the
# axis position pins.
. ../lib.sh
machine_start
machine_on
press mode.joint
bus wait traj.mode FREE 5 || exit 1
halcmd setp halui.joint.jog-speed 600 || exit 1
halcmd setp halui.joint.0.plus 1 || exit 1
sleep 0.4
halcmd setp halui.joint.0.plus 0 || exit 1
bus wait traj.jogging 0 5 || exit 1
bus wait joint.0.velocity 0.000000 5 || exit 1
a=$(halcmd getp joint.0.pos-cmd)
sleep 0.2
b=$(halcmd getp joint.0.pos-cmd)
awk -v a="$a" -v b="$b" 'BEGIN { print (a > 0.5 && a == b) ? "joint 0 jogged plus and stopped" : "joint 0 at " a " then " b }'
halcmd setp halui.joint.0.analog -0.5 || exit 1
sleep 0.3
halcmd setp halui.joint.0.analog 0.1 || exit 1
bus wait joint.0.velocity 0.000000 5 || exit 1
c=$(halcmd getp joint.0.pos-cmd)
awk -v b="$b" -v c="$c" 'BEGIN { print (c < b) ? "analog jog went minus and stopped in the deadband" : "joint 0 at " b " then " c }'
halcmd setp halui.joint.1.increment 2.5 || exit 1
press joint.1.increment-minus
bus wait joint.1.pos_cmd -2.500000 5 || exit 1
press joint.2.select
wait_pin joint.selected 2
echo "selected joint $(pin joint.selected): 2 $(pin joint.2.is-selected) 0 $(pin joint.0.is-selected)"
halcmd setp halui.joint.selected.increment 1.25 || exit 1
press joint.selected.increment-plus
bus wait joint.2.pos_cmd 1.250000 5 || exit 1
press mode.teleop
bus wait traj.mode TELEOP 5 || exit 1
halcmd setp halui.axis.jog-speed 1200 || exit 1
halcmd setp halui.axis.y.increment 3 || exit 1
press axis.y.increment-plus
bus wait axis.y.pos_cmd 0.500000 5 || exit 1
press axis.z.select
echo "selected axis $(pin axis.selected): z $(pin axis.z.is-selected) x $(pin axis.x.is-selected)"
halcmd setp halui.axis.selected.increment 0.75 || exit 1
press axis.selected.increment-minus
bus wait axis.z.pos_cmd 0.500000 5 || exit 1
halcmd setp halui.axis.x.minus 1 || exit 1
sleep 0.3
halcmd setp halui.axis.x.minus 0 || exit 1
bus wait traj.jogging 0 5 || exit 1
bus wait axis.x.velocity 0.000000 5 || exit 1
d=$(bus status axis.x.pos_cmd)
awk -v c="$c" -v d="$d" 'BEGIN { print (d < c - 0.5) ? "axis x jogged minus and stopped" : "x at " c " then " d }'
# halui copies the status to its pins at 50 Hz: give it a few of its cycles to show x's stop
x_matches() {
	awk -v p="$(pin axis.x.pos-commanded)" -v d="$d" 'BEGIN { print (p - d < 0.001 && d - p < 0.001) ? "yes" : "no" }'
}
n=0
while [ "$(x_matches)" != yes ] && [ $n -lt 50 ]; do sleep 0.05; n=$((n + 1)); done
printf 'pins y %.3f z %.3f x-matches %s\n' "$(pin axis.y.pos-commanded)" "$(pin axis.z.pos-feedback)" "$(x_matches)"
joints | sed 's/joints [^ ]* /joints X /'
machine_stop
