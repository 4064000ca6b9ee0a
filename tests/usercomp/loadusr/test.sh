# loadusr -Wn waits until the slow component is ready; show comp lists it as User with
# its PID; unloadusr sends SIGTERM and waits until the process and its pins are gone.
pidof_comp() { halcmd -s show comp "$1" | awk '{ print $4 }'; }
halcmd loadusr -Wn tc hal_testcomp tc 300
echo "loadusr -Wn: $?"
halcmd -s show comp tc | awk '{ print $2, $3, $5 }'
pid=$(pidof_comp tc)
halcmd -s show comp tc | grep -q " $pid " && [ "$pid" -gt 0 ] && echo "pid column: a number"
halcmd setp tc.in 1.25
sleep 0.2
halcmd getp tc.out
halcmd unloadusr tc
echo "unloadusr: $?"
kill -0 "$pid" 2>/dev/null && echo "process still there" || echo "process gone"
halcmd -s show pin tc
halcmd loadusr -Wn other hal_testcomp tc2 2>&1 | sed 's/ [0-9]* s / N s /'
halcmd unloadusr tc2
halrun -U
echo "halrun -U: $?"
