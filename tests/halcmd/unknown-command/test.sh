halrun -k -f bad.hal
echo "exit $?"
halcmd frobnicate
echo "exit $?"
