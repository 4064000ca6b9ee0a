# A full circle (R 5 about (5, 0), G3) through motcmd: the X/Y joint positions sampled
# every servo period stay on the true circle (cubic interpolation included) and
# within each joint's MAX_VELOCITY 10 / MAX_ACCELERATION 100; the feed 8 is cut to
# sqrt(0.866 * 100 * 5) = 20.8 > 8, so the circle runs at F.
. ../lib.sh
motion_load 3
tp_sample
halcmd start || exit 1
motion_config 3 10 100
motcmd enable || exit 1
motcmd coord || exit 1
motcmd wait-state coord 10 || exit 1
capture_start "$T/circle.txt"
motcmd arc 0 0 0 5 0 0 0 0 1 0 8 100 || exit 1
sleep 0.2
motcmd wait-inpos 30 || exit 1
capture_stop
motion_pathcheck circle 0.001 5 0 5 8 10 100 <"$T/circle.txt"
motcmd errors
rm -f config.cmd
halrun -U
