halrun -k -f syntax.hal
echo "exit $?"
