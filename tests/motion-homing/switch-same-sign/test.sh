# One joint, switch closed above 1.0; search +2, latch +0.5 (same sign: back off, then
# latch on the rising edge); HOME_OFFSET 0, HOME -0.5: ends at motor position 0.5.
. ../lib.sh
homing_machine 1
halcmd setp comp.0.in0 1.0
halcmd start
joint_limits 0
motcmd set-joint-homing 0 0 -0.5 -1 2 0.5 0 0 || exit 1
motcmd enable || exit 1
motcmd home 0 || exit 1
motcmd wait-homed 30 || exit 1
motcmd errors
stop_and_sample "$TEST_TMPDIR/s"
echo "home-state: $(states "$TEST_TMPDIR/s" 1)"
for p in joint.0.homed joint.0.homing joint.0.home-state axis.0.homed axis.0.home-state; do
	echo "$p $(halcmd getp $p)"
done
pos joint.0.pos-cmd 3
pos joint.0.motor-pos-cmd 2
pos joint.0.motor-offset 2
halrun -U
