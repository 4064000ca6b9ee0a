# G61: the square stops exactly on each corner (the sampled X/Y joint positions pass
# through every corner point) and keeps each axis within its limits.
. ../lib.sh
motion_load 3
tp_sample
halcmd start || exit 1
motion_config 3 10 100
tp_square_run square.txt exact
echo "$(tp_analyze 0.001 10 100 0)"
motcmd errors
rm -f square.txt square.cmd config.cmd
halrun -U
