halrun -f bad.hal
echo "exit $?"
halrun -k -f bad.hal
echo "exit $?"
