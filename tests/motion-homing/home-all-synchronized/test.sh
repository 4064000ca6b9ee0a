# Three joints, Home-All: joint 2 has HOME_SEQUENCE 0 (switch above 0.5); joints 0 and
# 1 have -1 and 1 (one negative member makes the group synchronized), switches above
# 1.0 and 2.0. Joint 2 finishes before the group starts; joint 0 waits at
# FINAL_MOVE_START (20) for joint 1, and both start their final move (21) in the same
# servo period. Then motion is all homed and switches to TELEOP by itself.
. ../lib.sh
homing_machine 3
halcmd setp comp.0.in0 1.0
halcmd setp comp.1.in0 2.0
halcmd setp comp.2.in0 0.5
halcmd start
for j in 0 1 2; do joint_limits $j; done
motcmd set-joint-homing 0 0 -0.5 -1 2 0.5 0 -1 || exit 1
motcmd set-joint-homing 1 0 -0.5 -1 2 0.5 0 1 || exit 1
motcmd set-joint-homing 2 0 -0.25 -1 2 0.5 0 0 || exit 1
motcmd enable || exit 1
motcmd home all || exit 1
motcmd wait-homed 60 || exit 1
motcmd wait-state teleop 5 || exit 1
motcmd errors
motcmd status | head -1
stop_and_sample "$TEST_TMPDIR/s"
for j in 0 1 2; do echo "joint $j home-state: $(states "$TEST_TMPDIR/s" $((j + 1)))"; done
f0=$(first_index "$TEST_TMPDIR/s" 1 21)
f1=$(first_index "$TEST_TMPDIR/s" 2 21)
[ "$f0" = "$f1" ] && echo "final moves start together" || echo "final moves at $f0 and $f1"
s0=$(first_index "$TEST_TMPDIR/s" 1 6)
e2=$(last_index_not "$TEST_TMPDIR/s" 3 0)
[ "$e2" -lt "$s0" ] && echo "sequence 0 before sequence 1" || echo "joint 2 ended at $e2, joint 0 started at $s0"
for j in 0 1 2; do
	echo "joint.$j.homed $(halcmd getp joint.$j.homed)"
	pos joint.$j.motor-pos-cmd 2
done
halcmd getp motion.is-all-homed
halrun -U
