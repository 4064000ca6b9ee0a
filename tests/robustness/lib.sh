# lib.sh - shared by the tests in tests/robustness (sourced by their test.sh).
# The rtapi_app serving this test's RTAPI_INSTANCE (several run in parallel).
rtapi_app_pid() {
	for p in /proc/[0-9]*; do
		[ "$(cat "$p/comm" 2>/dev/null)" = rtapi_app ] || continue
		{ tr '\0' '\n' < "$p/environ"; } 2>/dev/null | grep -qx "RTAPI_INSTANCE=$RTAPI_INSTANCE" &&
			echo "${p#/proc/}" && return 0
	done
	return 1
}

# kill -9 a process and wait (at most 10 s) until it is gone.
kill_and_wait() {
	kill -9 "$1" 2>/dev/null
	n=0
	while kill -0 "$1" 2>/dev/null && [ $n -lt 1000 ]; do
		sleep 0.01
		n=$((n + 1))
	done
}
