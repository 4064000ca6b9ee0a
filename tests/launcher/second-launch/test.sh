# A second launch while one runs: without a terminal to ask, it stops the first (which
# cleans up and exits 0) and comes up itself. A stale lock (its pid gone) is removed.
. ../common.sh
start_bg "$T/one" m.ini
first=$EMC_PID
wait_text "$T/one" "running headless" || exit 1
start_bg "$T/two" m.ini
wait_text "$T/two" "running headless" || exit 1
wait_status $first
sed -n "s|(pid [0-9]*)|(pid N)|;/still running/p" "$T/two"
[ "$(cat "$EMC_LOCK_FILE")" = "$EMC_PID" ] && echo "lock held by the second"
kill -0 $first 2>/dev/null && echo "first still running"
kill -TERM $EMC_PID
wait_status $EMC_PID
left
echo "== stale lock"
sh -c 'exit 0' &
dead=$!
wait $dead
echo $dead > "$EMC_LOCK_FILE"
start_bg "$T/three" m.ini
wait_text "$T/three" "running headless" || exit 1
sed -n "s|$T|TMP|;/stale/p" "$T/three"
kill -TERM $EMC_PID
wait_status $EMC_PID
left
