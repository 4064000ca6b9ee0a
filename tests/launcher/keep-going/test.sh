# -k: the failing line is reported and the launch goes on (the rest of bad.hal, the
# next file, task, start); SIGTERM then ends the headless session cleanly.
. ../common.sh
start_bg "$T/out" -k m.ini
wait_text "$T/out" "running headless" || exit 1
comps
kill -TERM $EMC_PID
wait_status $EMC_PID
sed -e "s|$PWD|.|g" -e '/^emc: /d' "$T/out"
grep -c "going on (-k)" "$T/out"
probe_log
left
