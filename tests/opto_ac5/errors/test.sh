# opto_ac5 load refusals (no board, points that do not exist) and sim_opto_ac5's
# count check print their message and leave nothing loaded.
halrun -k -f errors.hal
echo "exit $?"
