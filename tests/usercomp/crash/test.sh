# A userspace component killed with SIGKILL (no hal_exit) is cleaned up: the next
# halcmd show removes it, its pins are unlinked from the signals, the HAL memory it
# took (component, pins, hal_malloc) is returned and its name can be used again.
# Also when its parent has not reaped it yet (a zombie still answers kill -0).
memory() { halcmd status | grep -E 'used|active'; }
halcmd loadrt threads name1=t period1=1000000    # keeps the session between commands
halcmd newsig x float
halcmd newsig y float
before=$(memory)
halcmd loadusr -W hal_testcomp hal_testcomp
halcmd net x hal_testcomp.out
halcmd net y hal_testcomp.in
halcmd sets y 2
sleep 0.2
halcmd gets x
pid=$(halcmd -s show comp hal_testcomp | awk '{ print $4 }')
kill -9 "$pid"
while kill -0 "$pid" 2>/dev/null && [ "$(sed 's/.*) //' /proc/$pid/stat 2>/dev/null | cut -c1)" != Z ]; do sleep 0.05; done
halcmd -s show comp hal_testcomp
echo "listed after the crash: $(halcmd -s show comp hal_testcomp | wc -l)"
halcmd -s show sig
[ "$before" = "$(memory)" ] && echo "memory returned" || { echo "memory differs:"; echo "$before"; memory; }
halcmd loadusr -W hal_testcomp hal_testcomp
echo "same name again: $?"
halcmd -s show comp hal_testcomp | awk '{ print $2, $3, $5 }'
halcmd unloadusr hal_testcomp
# The zombie case: the component's parent ('sleep', which the shell execs into after
# starting it) never reaps it, so after SIGKILL it stays a zombie.
halcmd loadusr -Wn z sh -c 'hal_testcomp z & exec sleep 60'
zpid=$(halcmd -s show comp z | awk '{ print $4 }')
parent=$(sed 's/.*) . //' /proc/$zpid/stat | cut -d' ' -f1)
kill -9 "$zpid"
while [ "$(sed 's/.*) //' /proc/$zpid/stat 2>/dev/null | cut -c1)" != Z ]; do sleep 0.05; done
echo "zombie: $(sed 's/.*) //' /proc/$zpid/stat | cut -c1)"
echo "zombie listed: $(halcmd -s show comp z | wc -l)"
[ "$before" = "$(memory)" ] && echo "memory returned" || { echo "memory differs:"; echo "$before"; memory; }
kill "$parent"
halrun -U
echo "halrun -U: $?"
