halcmd help net
halcmd -h setp
halcmd help nosuch
echo "exit $?"
halcmd -h nosuch
echo "exit $?"
halcmd help | grep -c '^  '
halcmd -x
echo "exit $?"
