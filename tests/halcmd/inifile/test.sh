halrun -k -i machine.ini -f ini.hal
echo "exit $?"
halrun -i nosuch.ini -f ini.hal
echo "exit $?"
