# External offsets (motion.md 4.2, 3 step 13): X's offset is counts x scale, reached at
# the external-offset velocity 5 and acceleration 50 (checked on joint 0 sampled every
# period), added to the coordinated command (axis.x.pos-cmd stays without it), clipped
# so X stays inside its limits, back to 0 with eoffset-clear; nothing in FREE.
. ../lib.sh
motion_load 3
motion_sample 0
halcmd start || exit 1
motion_config 3 10 100
motcmd set-axis-eoffset-limits x 5 50 || exit 1
motcmd set-axis-limits x -10 10 || exit 1
show() {
	printf '%s: joint %.6f axis.x.pos-cmd %.6f eoffset %.6f request %.6f active %s limited %s\n' "$1" \
		"$(halcmd getp joint.0.pos-cmd)" "$(halcmd getp axis.x.pos-cmd)" \
		"$(halcmd getp axis.x.eoffset)" "$(halcmd getp axis.x.eoffset-request)" \
		"$(halcmd getp motion.eoffset-active)" "$(halcmd getp motion.eoffset-limited)"
}
# settle LABEL: a period for the pins to be read, wait until in position, show
settle() {
	sleep 0.05
	motcmd wait-inpos 10 || exit 1
	show "$1"
}
halcmd setp axis.x.eoffset-scale 0.01
halcmd setp axis.x.eoffset-enable 1
motcmd enable || exit 1
motcmd wait-state free 5 || exit 1
halcmd setp axis.x.eoffset-counts 50
sleep 0.05
show "FREE, 50 counts"
motcmd coord || exit 1
motcmd wait-state coord 5 || exit 1
echo "== COORD: +100 counts x 0.01"
capture_start "$T/eoffset.txt"
halcmd setp axis.x.eoffset-counts 150
sleep 0.05
motcmd wait-inpos 5 || exit 1
capture_stop
show "offset 1"
echo "offset move: $(motion_analyze 0.001 <"$T/eoffset.txt" | cut -d' ' -f1-4) (limits 5, 50)"
echo "== a coordinated move to X 3 carries the offset"
motcmd line 3 0 0 10 100 || exit 1
motcmd wait-inpos 5 || exit 1
show "X 3"
echo "== +900 counts: 10 asked, X may reach 10"
halcmd setp axis.x.eoffset-counts 1050
settle "clipped"
echo "== eoffset-enable FALSE: counts dropped"
halcmd setp axis.x.eoffset-enable 0
halcmd setp axis.x.eoffset-counts 0
settle "disabled"
echo "== eoffset-clear"
halcmd setp axis.x.eoffset-clear 1
settle "cleared"
halcmd setp axis.x.eoffset-clear 0
halcmd setp axis.x.eoffset-enable 1
halcmd setp axis.x.eoffset-counts -100
settle "-100 counts"
echo "== FREE: the joint stays, the offset is gone"
motcmd free || exit 1
motcmd wait-state free 5 || exit 1
sleep 0.05
show "FREE"
motcmd errors
halrun -U
