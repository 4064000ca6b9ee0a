# jog-incr and jog-cont: joint positions sampled every period never exceed
# MAX_VELOCITY (10) / MAX_ACCELERATION (100) and reach them exactly; a jog slower
# than the limit keeps its own speed; jog-cont is clipped to the joint's velocity.
. ../lib.sh
motion_load 1
motion_sample 0
halcmd start || exit 1
motion_config 1 10 100
motcmd enable || exit 1
capture_start "$T/incr.txt"
motcmd jog-incr 0 2 5 || exit 1
motcmd wait-inpos 10 || exit 1
capture_stop
echo "jog-incr 2 at 5: $(motion_analyze 0.001 <"$T/incr.txt")"
capture_start "$T/cont.txt"
motcmd jog-cont 0 -100 || exit 1
sleep 0.4
motcmd jog-abort 0 || exit 1
motcmd wait-inpos 10 || exit 1
capture_stop
echo "jog-cont at -100: $(motion_analyze 0.001 <"$T/cont.txt" | cut -d' ' -f1-4)"
capture_start "$T/abs.txt"
motcmd jog-abs 0 3 50 || exit 1
motcmd wait-inpos 10 || exit 1
capture_stop
echo "jog-abs 3 at 50: $(motion_analyze 0.001 <"$T/abs.txt")"
motcmd errors
halrun -U
