halrun -k -f errors.hal
echo "exit $?"
