# LOCKING_INDEXER (flag UNLOCK_FIRST 8) on a joint in unlock_joints_mask: homing sets
# joint.0.unlock and waits for joint.0.is-unlocked (looped back through the EMC2
# names axis.0.unlock / axis.0.is-unlocked, so the indexer answers one period later),
# homes (no search: HOME_OFFSET 0, HOME 2), then drops unlock and waits for
# is-unlocked to drop. Joint 1 is not in the mask: it has no unlock pins.
. ../lib.sh
halcmd -f <<'HAL' || exit 1
loadrt trivkins coordinates=xy
loadrt motmod servo_period_nsec=1000000 num_joints=2 unlock_joints_mask=1
loadrt sampler depth=40000 cfg=sb
net m0 joint.0.motor-pos-cmd => joint.0.motor-pos-fb
net m1 joint.1.motor-pos-cmd => joint.1.motor-pos-fb
net unlock axis.0.unlock => axis.0.is-unlocked sampler.0.pin.1
net st joint.0.home-state => sampler.0.pin.0
addf motion-command-handler servo-thread
addf motion-controller servo-thread
addf sampler.0 servo-thread
start
HAL
halcmd getp joint.1.unlock 2>&1
joint_limits 0
motcmd deactivate 1 || exit 1	# all homed = joint 0 homed
motcmd set-joint-homing 0 0 2 -1 0 0 8 0 || exit 1
motcmd enable || exit 1
motcmd home 0 || exit 1
motcmd wait-homed 30 || exit 1
motcmd errors
stop_and_sample "$TEST_TMPDIR/s"
echo "home-state: $(states "$TEST_TMPDIR/s" 1)"
echo "unlock: $(states "$TEST_TMPDIR/s" 2)"
u0=$(first_index "$TEST_TMPDIR/s" 2 1)
u1=$(last_index_not "$TEST_TMPDIR/s" 2 0)
[ "$u0" = "$(first_index "$TEST_TMPDIR/s" 1 3)" ] && echo "unlock set entering UNLOCK_WAIT" || echo "unlock set at $u0"
[ "$((u1 + 1))" = "$(first_index "$TEST_TMPDIR/s" 1 23)" ] && echo "unlock dropped entering LOCK_WAIT" || echo "unlock dropped after $u1"
echo "joint.0.homed $(halcmd getp joint.0.homed) unlock $(halcmd getp joint.0.unlock)"
pos joint.0.pos-cmd 3
halrun -U
