# loadusr -W/-Wn that times out stops the program it started (SIGTERM, or SIGKILL when
# SIGTERM is ignored) and says so; -Wn NAME refuses a NAME that exists already;
# a bad HALCMD_READY_TIMEOUT is refused. (pids vary: shown as N)
export HALCMD_READY_TIMEOUT=1
pids=$TEST_TMPDIR
gone() { if kill -0 "$(cat "$pids/$1")" 2>/dev/null; then echo "$1: still running"; else echo "$1: gone"; fi; }
halcmd loadusr -Wn nevercomp sh -c "echo \$\$ > $pids/term; exec sleep 30" 2>&1 | sed 's/pid [0-9]*/pid N/'
gone term
halcmd loadusr -Wn nevercomp sh -c "trap '' TERM; echo \$\$ > $pids/kill; exec sleep 30" 2>&1 | sed 's/pid [0-9]*/pid N/'
gone kill
HALCMD_READY_TIMEOUT=0 halcmd loadusr -W true
echo "exit $?"
halcmd loadrt and2
halcmd loadusr -Wn and2 sh -c "echo \$\$ > $pids/never; exec sleep 30"
echo "exit $?"
[ -e "$pids/never" ] && echo "started anyway" || echo "nothing started"
halcmd unloadrt and2
halrun -U
