# Spindle, coolant, lube and tool pins: spindle.0.forward (S0: 500 rpm, then the
# active S), increase, reverse, stop, brake; mist/flood/lube on and off (io's status
# and the is-on pins); tool.number, tool.diameter and tool.length_offset.z after M61
# and G43.
. ../lib.sh
machine_start
machine_on
spindle() {
	echo "$1: speed $(bus status spindle.0.speed) on $(pin spindle.0.is-on) fwd $(pin spindle.0.runs-forward) back $(pin spindle.0.runs-backward) brake $(pin spindle.0.brake-is-on)"
}
press spindle.0.forward
bus wait spindle.0.direction 1 5 || exit 1
wait_pin spindle.0.runs-forward TRUE
spindle forward
press spindle.0.increase
bus wait spindle.0.speed 600.000000 5 || exit 1
spindle increase
press spindle.0.reverse
bus wait spindle.0.direction -1 5 || exit 1
wait_pin spindle.0.runs-backward TRUE
spindle reverse
press spindle.0.stop
bus wait spindle.0.enabled 0 5 || exit 1
wait_pin spindle.0.is-on FALSE
spindle stop
# motion engages the brake when the spindle stops: release it, engage it again
press spindle.0.brake-off
wait_pin spindle.0.brake-is-on FALSE
spindle brake-off
press spindle.0.brake-on
wait_pin spindle.0.brake-is-on TRUE
spindle brake-on
press mode.mdi
bus wait task.mode MDI 5 || exit 1
bus mdi S1200 || exit 1
press spindle.0.start
bus wait spindle.0.direction 1 5 || exit 1
wait_pin spindle.0.is-on TRUE
spindle "start after S1200"
press spindle.0.stop
for c in mist flood; do
	press $c.on
	bus wait io.$c 1 5 || exit 1
	wait_pin $c.is-on TRUE
	echo "$c on: $(pin $c.is-on)"
	press $c.off
	bus wait io.$c 0 5 || exit 1
	wait_pin $c.is-on FALSE
	echo "$c off: $(pin $c.is-on)"
done
echo "lube with the machine on: $(pin lube.is-on)"
press lube.off
bus wait io.lube 0 5 || exit 1
wait_pin lube.is-on FALSE
press lube.on
bus wait io.lube 1 5 || exit 1
wait_pin lube.is-on TRUE
echo "lube off and on again: $(pin lube.is-on)"
bus mdi M61 Q2 || exit 1
bus mdi G43 || exit 1
wait_pin tool.number 2
wait_pin tool.length_offset.z 20.5
echo "tool $(pin tool.number) diameter $(pin tool.diameter) length z $(pin tool.length_offset.z) x $(pin tool.length_offset.x)"
machine_stop
