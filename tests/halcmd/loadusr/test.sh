halrun -k -f usr.hal
echo "exit $?"
