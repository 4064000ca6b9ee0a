halrun -k -f atomic.hal
echo "exit $?"
