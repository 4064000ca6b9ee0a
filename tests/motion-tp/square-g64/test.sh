# G64 P0.01: the square's commanded X/Y joint positions, sampled every servo period,
# stay within 0.01 of the programmed path, pass no corner point, and keep each axis
# within MAX_VELOCITY 10 / MAX_ACCELERATION 100.
. ../lib.sh
motion_load 3
tp_sample
halcmd start || exit 1
motion_config 3 10 100
tp_square_run square.txt blend 0.01
echo "$(tp_analyze 0.001 10 100 0.01 <square.txt)"
motcmd errors
rm -f square.txt square.cmd config.cmd
halrun -U
