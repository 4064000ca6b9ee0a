halrun -k -f cmds.hal
echo "exit $?"
