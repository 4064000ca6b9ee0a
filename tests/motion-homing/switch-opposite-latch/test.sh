# One joint, switch closed above 1.0, wired through the EMC2 name axis.0.home-sw-in;
# search +2, latch -0.5 (opposite sign: latch on the falling edge while leaving the
# switch); HOME_OFFSET 0.2, HOME 0: the edge reads 0.2, so HOME is motor position 0.8.
. ../lib.sh
homing_machine 1 emc2
halcmd setp comp.0.in0 1.0
halcmd start
joint_limits 0
motcmd set-joint-homing 0 0.2 0 -1 2 -0.5 0 0 || exit 1
motcmd enable || exit 1
motcmd home 0 || exit 1
motcmd wait-homed 30 || exit 1
motcmd errors
stop_and_sample "$TEST_TMPDIR/s"
echo "home-state: $(states "$TEST_TMPDIR/s" 1)"
echo "joint.0.homed $(halcmd getp joint.0.homed)"
pos joint.0.pos-cmd 3
pos joint.0.motor-pos-cmd 2
halrun -U
