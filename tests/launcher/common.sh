# Shared by the tests/launcher cases (sourced from each test.sh, POSIX sh: it runs in
# the kernel-test VM's busybox too). Each case works in TEST_TMPDIR with its own lock
# file, probe log and rc file; launch_probe (tests/helpers) stands in for io and task.
T=${TEST_TMPDIR:-/tmp}
export EMC_LOCK_FILE="$T/emc.lock" LAUNCH_PROBE_LOG="$T/probe.log" EMC_RC_FILE="$T/emcrc"
rm -f "$LAUNCH_PROBE_LOG"

# start_bg OUT ARGS...: emc -v ARGS in the background, its stderr+stdout to OUT;
# EMC_PID is its pid.
start_bg() {
	out=$1
	shift
	emc -v "$@" > "$out" 2>&1 < /dev/null &
	EMC_PID=$!
}

# wait_text FILE TEXT [SECONDS]: until FILE holds TEXT (default 60 s); 1 on time-out.
wait_text() {
	n=0
	while ! grep -q -- "$2" "$1" 2>/dev/null; do
		n=$((n + 1))
		[ $n -gt $(( ${3:-60} * 10 )) ] && { echo "timed out waiting for '$2' in $1"; cat "$1"; return 1; }
		sleep 0.1
	done
}

# wait_status PID: until that background emc has exited; prints "exit N".
wait_status() {
	wait "$1"
	echo "exit $?"
}

# What a session leaves: HAL segments (sim) or hal_lib.ko (kernel), probe processes
# still alive, the lock file. "left: 0 0 no" is clean.
left() {
	if [ "$HAL_TEST_FLAVOR" = kernel ]; then
		seg=$(grep -c '^hal_lib ' /proc/modules)
	else
		seg=$(ls /dev/shm | grep -c -- "-${RTAPI_INSTANCE:-0}-")
	fi
	procs=0
	for p in $(sed -n 's/^start [^ ]* pid=\([0-9]*\).*/\1/p' "$LAUNCH_PROBE_LOG" 2>/dev/null); do
		kill -0 "$p" 2>/dev/null && procs=$((procs + 1))
	done
	lock=no
	[ -e "$EMC_LOCK_FILE" ] && lock=yes
	echo "left: $seg $procs $lock"
}

# The probe log without pids and paths that vary.
probe_log() {
	sed -e 's/ pid=[0-9]*//' -e "s|$PWD|.|g" -e "s|$T|TMP|g" "$LAUNCH_PROBE_LOG"
}

# halcmd show comp, without the PID column's values.
comps() {
	halcmd show comp | sed -e 's/  *[0-9][0-9]*  *ready$/ PID ready/' -e 's/ *$//'
}
