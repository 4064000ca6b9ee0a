halcmd loadrt and2 count=-1
echo "exit $?"
halcmd loadrt siggen num_chan=-3
echo "exit $?"
halcmd loadrt and2 "count=1$(printf '\001')"
echo "exit $?"
halcmd loadrt and2 count=2
echo "exit $?"
halcmd list comp
