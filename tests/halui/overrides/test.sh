# The override knobs through halui: counts x scale added to the current value,
# count-enable FALSE absorbing counts, direct-value, increase/decrease/reset edges,
# clamped to the INI's limits ([DISPLAY]MAX_FEED_OVERRIDE 1.5, rapid 1.0,
# MIN/MAX_SPINDLE_OVERRIDE 0.5/1.2, [TRAJ]MAX_LINEAR_VELOCITY 80); task's status and
# the value pins show each result.
. ../lib.sh
machine_start
show() {
	bus wait "$1" "$2" 5 || exit 1
	wait_pin "$3" "$(printf %g "$2")"
	echo "$3 $(pin "$3")"
}
echo "start: feed $(pin feed-override.value) rapid $(pin rapid-override.value) spindle $(pin spindle.0.override.value) max-velocity $(pin max-velocity.value)"
halcmd setp halui.feed-override.counts 3 || exit 1
show traj.feed_scale 1.300000 feed-override.value
halcmd setp halui.feed-override.counts 10 || exit 1
show traj.feed_scale 1.500000 feed-override.value
halcmd setp halui.feed-override.count-enable 0 || exit 1
halcmd setp halui.feed-override.counts 40 || exit 1
sleep 0.2
halcmd setp halui.feed-override.count-enable 1 || exit 1
halcmd setp halui.feed-override.counts 35 || exit 1
show traj.feed_scale 1.000000 feed-override.value
halcmd setp halui.feed-override.direct-value 1 || exit 1
halcmd setp halui.feed-override.scale 0.01 || exit 1
halcmd setp halui.feed-override.counts 75 || exit 1
show traj.feed_scale 0.750000 feed-override.value
press feed-override.reset
show traj.feed_scale 1.000000 feed-override.value
press rapid-override.decrease
show traj.rapid_scale 0.900000 rapid-override.value
press rapid-override.increase
press rapid-override.increase
show traj.rapid_scale 1.000000 rapid-override.value
halcmd setp halui.rapid-override.counts -20 || exit 1
show traj.rapid_scale 0.000000 rapid-override.value
press spindle.0.override.decrease
show spindle.0.override 0.900000 spindle.0.override.value
halcmd setp halui.spindle.0.override.counts -10 || exit 1
show spindle.0.override 0.500000 spindle.0.override.value
halcmd setp halui.spindle.0.override.direct-value 1 || exit 1
halcmd setp halui.spindle.0.override.counts 13 || exit 1
show spindle.0.override 1.200000 spindle.0.override.value
press spindle.0.override.reset
show spindle.0.override 1.000000 spindle.0.override.value
halcmd setp halui.max-velocity.direct-value 1 || exit 1
halcmd setp halui.max-velocity.scale 1 || exit 1
halcmd setp halui.max-velocity.counts 200 || exit 1
show traj.max_velocity 80.000000 max-velocity.value
halcmd setp halui.max-velocity.counts 25 || exit 1
show traj.max_velocity 25.000000 max-velocity.value
halcmd setp halui.max-velocity.direct-value 0 || exit 1
press max-velocity.increase
show traj.max_velocity 26.000000 max-velocity.value
machine_stop
