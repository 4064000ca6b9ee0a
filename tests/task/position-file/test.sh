# [TRAJ]POSITION_FILE: task writes the joint positions when it exits (one %.17f per
# line, joint order) and the next start puts the joints there (motor offsets), after
# a full restart of HAL. A file that is not numbers stops task with FILE:LINE.
. ../lib.sh
awk '{ print } /^\[TRAJ\]/ { print "POSITION_FILE = pos.txt"; print "NO_FORCE_HOMING = 1" }' \
	../common/sim.ini > "$INI" || exit 1
task_start
bus state estop_reset || exit 1
bus state on || exit 1
bus mode mdi || exit 1
bus mdi G0 X12.5 Y-3.25 Z7 || exit 1
joints
task_stop
echo "-- the file"
cat "$T/pos.txt"
[ -e "$T/pos.txt.new" ] && echo "pos.txt.new left behind"
echo "-- HAL and task started again"
task_start
sleep 0.2
printf 'pos-fb %.3f %.3f %.3f\n' "$(halcmd getp joint.0.pos-fb)" "$(halcmd getp joint.1.pos-fb)" \
	"$(halcmd getp joint.2.pos-fb)"
printf 'motor-pos-cmd %.3f %.3f %.3f\n' "$(halcmd getp joint.0.motor-pos-cmd)" \
	"$(halcmd getp joint.1.motor-pos-cmd)" "$(halcmd getp joint.2.motor-pos-cmd)"
bus state estop_reset || exit 1
bus state on || exit 1
bus mode mdi || exit 1
bus mdi G1 X10 F600 || exit 1
joints
task_stop
echo "-- a damaged file"
printf '1.5\nabc\n' > "$T/pos.txt"
halcmd -f ../common/machine.hal || exit 1
halcmd start || exit 1
halcmd loadusr -Wn inihal milltask -ini "$INI" -bus "$BUS" > "$T/err" 2>&1
echo "exit $?"
sed "s|$T/||" "$T/err"
halrun -U
