# A userspace component killed with SIGKILL (no hal_exit) is cleaned up: the next
# halcmd show removes it and its pins are unlinked from the signals.
used() { halcmd status | awk '/used/ { print $0 }'; }
halcmd newsig x float
halcmd newsig y float
halcmd loadusr -W hal_testcomp hal_testcomp
halcmd net x hal_testcomp.out
halcmd net y hal_testcomp.in
halcmd sets y 2
sleep 0.2
halcmd gets x
pid=$(halcmd -s show comp hal_testcomp | awk '{ print $4 }')
kill -9 "$pid"
while kill -0 "$pid" 2>/dev/null; do sleep 0.05; done
halcmd -s show comp hal_testcomp
echo "listed after the crash: $(halcmd -s show comp hal_testcomp | wc -l)"
halcmd -s show sig
halcmd loadusr -W hal_testcomp hal_testcomp
echo "same name again: $?"
halcmd -s show comp hal_testcomp | awk '{ print $2, $3, $5 }'
halrun -U
echo "halrun -U: $?"
