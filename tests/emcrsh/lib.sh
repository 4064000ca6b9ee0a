# lib.sh - sourced by the emcrsh cases' test.sh (cwd: the case directory).
# The machine is tests/task's simulated three-axis mill (../../task/common: motion,
# io with loop-backs, milltask; homing sets the position at once); emcrsh serves it on
# a free port (-p 0: it prints the port it took), so parallel runs never collide.
# T, INI, BUS, bus CMD...: as in tests/task/lib.sh (sourced).
# machine_start / machine_stop: its task_start / task_stop.
# rsh_start [OPTIONS]: emcrsh in the background, PORT set. rsh [-t S]: rsh_client
#   to it, the script on stdin (tests/helpers/rsh_client.cpp). rsh_stop, machine_stop.
TASK_COMMON=../../task/common
. ../../task/lib.sh
. ../../../demo/wait-output.sh
trap 'rsh_stop; rm -rf "$T"' EXIT
rsh_pid=

machine_start() {
	task_start
}

machine_stop() {
	task_stop
}

# rsh_start [OPTIONS]: emcrsh OPTIONS -p 0 -- -ini INI -bus BUS; PORT := its port
rsh_start() {
	: > "$T/rsh.out"
	emcrsh -p 0 "$@" -- -ini "$INI" -bus "$BUS" > "$T/rsh.out" 2>&1 &
	rsh_pid=$!
	PORT=$(wait_output "$T/rsh.out" $rsh_pid 10 's/^emcrsh: listening on port \([0-9]*\)$/\1/p') || {
		echo "emcrsh did not start:"
		cat "$T/rsh.out"
		exit 1
	}
}

rsh() {
	rsh_client "$@" 127.0.0.1 "$PORT"
}

# rsh_alive: "emcrsh running" or "emcrsh gone"
rsh_alive() {
	if [ -n "$rsh_pid" ] && kill -0 "$rsh_pid" 2>/dev/null; then echo "emcrsh running"; else echo "emcrsh gone"; fi
}

rsh_stop() {
	if [ -n "$rsh_pid" ]; then
		kill "$rsh_pid" 2>/dev/null
		wait "$rsh_pid" 2>/dev/null
		rsh_pid=
	fi
}

# rsh_exited: waits for emcrsh to end (after SHUTDOWN) and prints its exit status
rsh_exited() {
	wait "$rsh_pid"
	echo "emcrsh exit $?"
	rsh_pid=
}
