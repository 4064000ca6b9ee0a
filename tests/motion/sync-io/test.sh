# Synchronized digital and analog outputs (motion.md 7.1 SET_DOUT/SET_AOUT, M62-M68):
# X, motion.digital-out-00 and motion.analog-out-00 sampled every servo period; the
# start value must appear in the period X starts to move, the end value in the
# period the planner reaches the move's end (X, interpolated, arrives two periods
# later: 1.99978 -> 1.99993 -> 2). Immediate ("now") outputs change at once.
. ../lib.sh
motion_load 3
halcmd loadrt sampler depth=8000 cfg=fbf || exit 1
halcmd net x joint.0.pos-cmd sampler.0.pin.0 || exit 1
halcmd net d0 motion.digital-out-00 sampler.0.pin.1 || exit 1
halcmd net a0 motion.analog-out-00 sampler.0.pin.2 || exit 1
halcmd addf sampler.0 servo-thread || exit 1
halcmd start || exit 1
motion_config 3 10 100
motion_coord
echo "== immediate"
motcmd dout 1 1 || exit 1
motcmd aout 1 7.25 || exit 1
sleep 0.05
echo "digital-out-01 $(halcmd getp motion.digital-out-01) analog-out-01 $(halcmd getp motion.analog-out-01)"
echo "== synchronized with the next move: on at its start, off at its end"
motcmd dout 0 1 sync 0 || exit 1
motcmd aout 0 2.5 sync -1 || exit 1
sleep 0.05
echo "before the move: digital-out-00 $(halcmd getp motion.digital-out-00) analog-out-00 $(halcmd getp motion.analog-out-00)"
capture_start "$T/io.txt"
motcmd line 2 0 0 10 100 || exit 1
motcmd wait-inpos 5 || exit 1
capture_stop
# each change of an output: the period, X before and in it
awk '{ if (n && $2 != d) printf "digital-out-00 %s -> %s: X %.6f -> %.6f\n", d, $2, px, $1
       if (n && $3 != a) printf "analog-out-00 %s -> %s: X %.6f -> %.6f\n", a, $3, px, $1
       if (n && $1 != px && !moved) { moved = 1; printf "X starts to move: %.6f -> %.6f\n", px, $1 }
       d = $2; a = $3; px = $1; n++ }' "$T/io.txt"
echo "== synchronized without an end value: stays"
motcmd dout 0 1 sync || exit 1
motcmd line 0 0 0 10 100 || exit 1
motcmd wait-inpos 5 || exit 1
echo "after the move: digital-out-00 $(halcmd getp motion.digital-out-00)"
echo "== refused: an output that does not exist"
motcmd dout 9 1 sync
echo "status $?"
motcmd errors
halrun -U
