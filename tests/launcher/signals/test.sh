# SIGTERM and SIGINT end a headless session: applications, [HAL]SHUTDOWN, task, then
# threads, components (io, halui) and realtime; exit 0 and nothing left (no process,
# no HAL segment or module, no lock file).
. ../common.sh
for sig in TERM INT; do
	echo "== SIG$sig"
	rm -f "$LAUNCH_PROBE_LOG"
	start_bg "$T/out" m.ini
	wait_text "$T/out" "running headless" || exit 1
	wait_text "$LAUNCH_PROBE_LOG" "start app" || exit 1
	kill -$sig $EMC_PID
	wait_status $EMC_PID
	probe_log | sed -n '/^start/p'
	probe_log | sed -n '/^start/!p' | head -3
	probe_log | sed -n '/^start/!p' | tail -n +4 | sort
	left
done
