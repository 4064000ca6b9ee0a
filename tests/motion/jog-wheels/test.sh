# Jog wheels (motion.md 12): position mode moves counts x scale, at the joint's (axis')
# MAX_VELOCITY and jog-accel-fraction x MAX_ACCELERATION, both checked on positions
# sampled every servo period; velocity mode leads by at most the stopping distance
# v^2/2a; counts whose target is outside the jog range are discarded; counts turned
# while the wheel is disabled, in the other mode or under motion.jog-inhibit are
# dropped, never applied later.
. ../lib.sh
motion_load 3
# joint 0 x 1e6 into sampler 0: one capture for the joint wheel, one for the axis
# wheel (capture_stop leaves nothing of the first for the second)
motion_sample 0
halcmd start || exit 1
motion_config 3 10 100
pos() { printf '%s X %.6f\n' "$1" "$(halcmd getp joint.0.pos-cmd)"; }
counts() { halcmd setp "$1.jog-counts" "$2" || exit 1; sleep 0.05; motcmd wait-inpos 5 || exit 1; }
motcmd enable || exit 1
motcmd wait-state free 5 || exit 1
halcmd setp joint.0.jog-scale 0.01
halcmd setp joint.0.jog-enable 1
halcmd setp joint.0.jog-accel-fraction 0.5
sleep 0.05
echo "== FREE, joint 0: 300 counts x 0.01, accel fraction 0.5"
capture_start "$T/wheel.txt"
counts joint.0 300
capture_stop
pos "300 counts"
echo "joint wheel: $(motion_analyze 0.001 <"$T/wheel.txt" | cut -d' ' -f1-4) (limits 10, 50)"
echo "== back 100 counts"
counts joint.0 200
pos "200 counts"
echo "== disabled: counts dropped"
halcmd setp joint.0.jog-enable 0
counts joint.0 500
halcmd setp joint.0.jog-enable 1
counts joint.0 500
pos "500 counts while disabled"
echo "== motion.jog-inhibit: counts dropped"
halcmd setp motion.jog-inhibit 1
counts joint.0 700
halcmd setp motion.jog-inhibit 0
counts joint.0 700
pos "700 counts while inhibited"
echo "== a target outside the jog range (200 from the feedback, unhomed) is discarded"
counts joint.0 100000
pos "+99300 counts"
echo "== velocity mode: leads by at most 10^2 / (2 x 100) = 0.5"
halcmd setp joint.0.jog-accel-fraction 1
halcmd setp joint.0.jog-vel-mode 1
counts joint.0 100500
pos "+500 counts"
halcmd setp joint.0.jog-vel-mode 0
echo "== axis X counts in FREE are dropped"
halcmd setp axis.x.jog-scale 0.001
halcmd setp axis.x.jog-enable 1
counts axis.x 1000
echo "== TELEOP, axis X: 2000 counts x 0.001, accel fraction 0.25"
motcmd teleop || exit 1
motcmd wait-state teleop 5 || exit 1
pos "entering teleop"
halcmd setp axis.x.jog-accel-fraction 0.25
halcmd setp joint.0.jog-counts 100800	# joint wheel in TELEOP: dropped
capture_start "$T/axis.txt"
counts axis.x 3000
capture_stop
pos "axis +2000 counts"
echo "axis wheel: $(motion_analyze 0.001 <"$T/axis.txt" | cut -d' ' -f1-4) (limits 10, 25)"
motcmd free || exit 1
motcmd wait-state free 5 || exit 1
counts joint.0 100800
pos "back in FREE, joint counts unchanged"
halrun -U
