# The EMC2 2.4 names of the seed halui(1) page load (emc2.hal nets and sets them) and
# work as aliases of today's pins: a jog through halui.jog.1.minus driven by its
# signal, the spindle through halui.spindle.start, its override through
# halui.spindle-override.increase, status through halui.axis.0.pos-commanded,
# halui.spindle.is-on, halui.joint.selected.is_homed and halui.tool.length-offset.z.
. ../lib.sh
machine_start
halcmd -f emc2.hal || exit 1
echo "jog-speed $(pin joint.jog-speed) deadband $(pin joint.jog-deadband) (set through the old names)"
for p in jog.0.plus:joint.0.plus jog.2.analog:joint.2.analog jog-deadband:joint.jog-deadband \
	jog.selected.minus:joint.selected.minus spindle.brake-on:spindle.0.brake-on \
	spindle-override.scale:spindle.0.override.scale spindle-override.count-enable:spindle.0.override.count-enable \
	spindle-override.direct-value:spindle.0.override.direct-value axis.2.pos-relative:axis.z.pos-relative \
	tool.length-offset.a:tool.length_offset.a joint.selected.on-soft-limit:joint.selected.on-soft-min-limit; do
	old=${p%%:*}
	new=${p#*:}
	[ "$(pin "$old")" = "$(pin "$new")" ] || echo "halui.$old differs from halui.$new"
done
machine_on
echo "selected joint homed (is_homed): $(halcmd gets sel-homed)"
press mode.joint
bus wait traj.mode FREE 5 || exit 1
halcmd sets jog1-minus 1 || exit 1
sleep 0.3
halcmd sets jog1-minus 0 || exit 1
bus wait traj.jogging 0 5 || exit 1
bus wait joint.1.velocity 0.000000 5 || exit 1
awk -v y="$(halcmd getp joint.1.pos-cmd)" 'BEGIN { print (y < -0.5) ? "halui.jog.1.minus jogged joint 1" : "joint 1 at " y }'
halcmd sets spindle-start 1 || exit 1
bus wait spindle.0.direction 1 5 || exit 1
sleep 0.1
halcmd sets spindle-start 0 || exit 1
n=0
while [ "$(halcmd gets spindle-is-on)" != TRUE ] && [ $n -lt 100 ]; do sleep 0.05; n=$((n + 1)); done
echo "halui.spindle.start: spindle.0 direction $(bus status spindle.0.direction), halui.spindle.is-on $(halcmd gets spindle-is-on)"
halcmd sets so-increase 1 || exit 1
bus wait spindle.0.override 1.100000 5 || exit 1
halcmd sets so-increase 0 || exit 1
echo "halui.spindle-override.increase: override $(bus status spindle.0.override)"
press mode.mdi
bus mdi G0 X7 || exit 1
bus mdi M61 Q1 || exit 1
bus mdi G43 || exit 1
n=0
while [ "$(halcmd gets z-tlo)" != 10 ] && [ $n -lt 100 ]; do sleep 0.05; n=$((n + 1)); done
echo "halui.axis.0.pos-commanded $(halcmd gets x-cmd), halui.tool.length-offset.z $(halcmd gets z-tlo)"
machine_stop
