# Spindle outputs (motion.md 4.4, 14) driven through motcmd: the pins after each
# command, the override and inhibit, the min/max clamps, CSS (speed = factor /
# |xoffset - X|, at most the commanded speed), the orient handshake and the at-speed
# gate of the first feed move after a spindle start that asks for it.
. ../lib.sh
motion_load 3
halcmd start || exit 1
motion_config 3 10 100
pins() {
	printf '%s: on %s fwd %s rev %s brake %s out %.3f abs %.3f rps %.4f rps-abs %.4f cmd-rps %.4f\n' "$1" \
		"$(halcmd getp spindle.0.on)" "$(halcmd getp spindle.0.forward)" \
		"$(halcmd getp spindle.0.reverse)" "$(halcmd getp spindle.0.brake)" \
		"$(halcmd getp spindle.0.speed-out)" "$(halcmd getp spindle.0.speed-out-abs)" \
		"$(halcmd getp spindle.0.speed-out-rps)" "$(halcmd getp spindle.0.speed-out-rps-abs)" \
		"$(halcmd getp spindle.0.speed-cmd-rps)"
}
# a command takes effect in the period that handles it; outputs one period later
settle() { sleep 0.05; }
motcmd spindle-params 0 100 3000 200 2000 100 || exit 1
motcmd enable || exit 1
motcmd wait-state free 5 || exit 1
pins "at start"
motcmd spindle-on 1200 || exit 1; settle; pins "on 1200"
motcmd spindle-on -600 || exit 1; settle; pins "on -600"
echo "EMC2 alias motion.spindle-reverse: $(halcmd getp motion.spindle-reverse)"
motcmd spindle-off || exit 1; settle; pins "off"
motcmd spindle-brake off || exit 1; settle; pins "brake released"
echo "== clamps (forward 100..3000, reverse 200..2000)"
motcmd spindle-on 50 || exit 1; settle; pins "on 50"
motcmd spindle-on 5000 || exit 1; settle; pins "on 5000"
motcmd spindle-on -100 || exit 1; settle; pins "on -100"
motcmd spindle-on -9000 || exit 1; settle; pins "on -9000"
echo "== override and inhibit"
motcmd spindle-on 1000 || exit 1
motcmd spindle-scale 1.5 || exit 1; settle; pins "scale 1.5"
motcmd ss-enable 0 || exit 1; settle; pins "scale 1.5, override disabled (M49)"
motcmd ss-enable 1 || exit 1
halcmd setp spindle.0.inhibit 1; settle; pins "inhibit"
halcmd setp spindle.0.inhibit 0
motcmd spindle-scale 1 || exit 1
echo "== increase / decrease by 100"
motcmd spindle-increase || exit 1; settle; pins "increase"
motcmd spindle-decrease || exit 1; motcmd spindle-decrease || exit 1; settle; pins "decrease twice"
echo "== CSS: factor 10000, xoffset 0, at most 2000 rpm"
motcmd jog-abs 0 10 10 || exit 1
motcmd wait-inpos 5 || exit 1
motcmd spindle-on 2000 0 10000 0 || exit 1; settle; pins "X 10"
motcmd jog-abs 0 20 10 || exit 1
motcmd wait-inpos 5 || exit 1
settle; pins "X 20"
motcmd jog-abs 0 2 10 || exit 1
motcmd wait-inpos 5 || exit 1
settle; pins "X 2 (clamped)"
motcmd spindle-on -2000 0 10000 0 || exit 1; settle; pins "X 2, reverse"
motcmd jog-abs 0 0 10 || exit 1
motcmd wait-inpos 5 || exit 1
settle; pins "X 0 (denominator 0: commanded speed)"
echo "== orient"
motcmd spindle-orient 45 2 || exit 1; settle; pins "orient"
printf 'orient %s angle %s mode %s locked %s\n' "$(halcmd getp spindle.0.orient)" \
	"$(halcmd getp spindle.0.orient-angle)" "$(halcmd getp spindle.0.orient-mode)" \
	"$(halcmd getp spindle.0.locked)"
halcmd setp spindle.0.is-oriented 1; settle
printf 'oriented: orient %s locked %s brake %s %s\n' "$(halcmd getp spindle.0.orient)" \
	"$(halcmd getp spindle.0.locked)" "$(halcmd getp spindle.0.brake)" \
	"$(motcmd status | grep '^spindle 0' | cut -d' ' -f11-12)"
halcmd setp spindle.0.is-oriented 0
motcmd spindle-on 500 || exit 1; settle
printf 'M3 after orient: locked %s brake %s\n' "$(halcmd getp spindle.0.locked)" "$(halcmd getp spindle.0.brake)"
motcmd spindle-orient 90 0 || exit 1; settle
halcmd setp spindle.0.orient-fault 7; settle
printf 'fault: orient %s locked %s %s\n' "$(halcmd getp spindle.0.orient)" \
	"$(halcmd getp spindle.0.locked)" "$(motcmd status | grep '^spindle 0' | cut -d' ' -f11-12)"
motcmd errors
halcmd setp spindle.0.orient-fault 0
echo "== at-speed gates the first feed move after a spindle start that waits"
motcmd coord || exit 1
motcmd wait-state coord 5 || exit 1
halcmd setp spindle.0.at-speed 0
motcmd spindle-on 1000 0 wait || exit 1
motcmd line 5 0 0 10 100 || exit 1
sleep 0.3
printf 'waiting: X %.6f queue %s\n' "$(halcmd getp joint.0.pos-cmd)" \
	"$(motcmd status | sed -n 3p | cut -d' ' -f3)"
halcmd setp spindle.0.at-speed 1
motcmd wait-inpos 5 || exit 1
printf 'at speed: X %.6f\n' "$(halcmd getp joint.0.pos-cmd)"
halcmd setp spindle.0.at-speed 0
motcmd line 6 0 0 10 100 || exit 1
motcmd wait-inpos 5 || exit 1
printf 'next feed move does not wait: X %.6f\n' "$(halcmd getp joint.0.pos-cmd)"
motcmd spindle-on 1000 0 || exit 1
motcmd line 7 0 0 10 100 || exit 1
motcmd wait-inpos 5 || exit 1
printf 'spindle start without wait: X %.6f\n' "$(halcmd getp joint.0.pos-cmd)"
echo "== spindle amplifier fault"
halcmd setp spindle.0.amp-fault-in 1
motcmd wait-state disabled 5 || exit 1
motcmd errors
halcmd setp spindle.0.amp-fault-in 0
echo "== a spindle that does not exist"
motcmd spindle-on 100 3
echo "status $?"
motcmd errors
halrun -U
