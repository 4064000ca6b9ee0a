# Two joints without switch search. Joint 0: SEARCH_VEL 0 and LATCH_VEL 0 (home where
# it stands: position := HOME_OFFSET 3, then the final move to HOME 4), VOLATILE_HOME.
# Joint 1: HOME_ABSOLUTE_ENCODER 2 (flags ABSOLUTE_ENCODER 16 + NO_REHOME 32 +
# NO_FINAL_MOVE 64): the reading (0.25: motor at 0, motor offset -0.25) plus
# HOME_OFFSET 5, no motion.
# Homing joint 1 again changes nothing (NO_REHOME). Machine off + UNHOME volatile:
# only joint 0 loses its home.
. ../lib.sh
homing_machine 2
halcmd start
joint_limits 0
joint_limits 1
motcmd set-joint-motor-offset 1 -0.25 || exit 1
motcmd set-joint-homing 0 3 4 -1 0 0 0 0 1 || exit 1
motcmd set-joint-homing 1 5 10 -1 0 0 112 1 || exit 1
motcmd enable || exit 1
motcmd home all || exit 1
motcmd wait-homed 30 || exit 1
motcmd errors
stop_and_sample "$TEST_TMPDIR/s"
halcmd start
echo "joint 0 home-state: $(states "$TEST_TMPDIR/s" 1)"
echo "joint 1 home-state: $(states "$TEST_TMPDIR/s" 2)"
for j in 0 1; do pos joint.$j.pos-cmd 3; pos joint.$j.motor-pos-cmd 3; done
motcmd wait-state teleop 5 || exit 1
motcmd free || exit 1
motcmd wait-state free 5 || exit 1
motcmd home 1 || exit 1
motcmd wait-inpos 5 || exit 1
pos joint.1.pos-cmd 3
motcmd disable || exit 1
motcmd unhome volatile || exit 1
motcmd errors
echo "after unhome volatile: joint.0.homed $(halcmd getp joint.0.homed) joint.1.homed $(halcmd getp joint.1.homed)"
halrun -U
