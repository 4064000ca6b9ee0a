# serport load refusals (no port, bad address, a port twice) print their message
# and leave nothing loaded.
halrun -k -f errors.hal
echo "exit $?"
