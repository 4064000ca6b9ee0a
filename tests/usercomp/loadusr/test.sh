# loadusr -Wn waits until the slow component is ready; show comp lists it as User with
# its PID; unloadusr sends SIGTERM and waits until the process and its pins are gone.
# gone: no such process, or a zombie (exited; its parent, init here, may reap it late
# or, in some containers, never)
gone() { ! kill -0 "$1" 2>/dev/null || [ "$(sed 's/.*) //' "/proc/$1/stat" 2>/dev/null | cut -c1)" = Z ]; }
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
gone "$pid" && echo "process gone" || echo "process still there"
halcmd -s show pin tc
# unloadusr of a name that is no longer loaded
halcmd unloadusr tc
echo "unloadusr again: $?"
halrun -U
echo "halrun -U: $?"
