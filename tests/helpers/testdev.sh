# testdev.sh - sourced by the tests that drive a virtual input device made by
# hal_testdev (uinput, uhid): the device on file descriptor 3, and waits that allow
# for qemu, where each halcmd takes a while (up to 15 s by the clock).
#   testdev_start KIND [ARGS...]  runs `hal_testdev KIND ARGS` fed from fd 3; waits
#                                 for its "ready NODE" line; sets TESTDEV_PID, node
#   wait_for FILE PATTERN         until PATTERN is in FILE (prints FILE on time-out)
#   wait_pin NAME VALUE           until `halcmd getp NAME` prints VALUE
#   memory                        the HAL's memory figures, to compare before/after
T=${TEST_TMPDIR:-/tmp}
wait_for() {
	end=$(($(date +%s) + 15))
	while ! grep -q "$2" "$1" 2>/dev/null; do
		[ "$(date +%s)" -gt $end ] && { echo "timed out waiting for '$2' in $1"; cat "$1"; return 1; }
		sleep 0.05
	done
}
wait_pin() {
	end=$(($(date +%s) + 15))
	while [ "$(halcmd getp "$1")" != "$2" ]; do
		[ "$(date +%s)" -gt $end ] && { echo "timed out waiting for $1 = $2 (is $(halcmd getp "$1"))"; return 1; }
		sleep 0.05
	done
}
memory() { halcmd status | grep -E 'used|active'; }
testdev_start() {
	rm -f "$T/ctl"; mkfifo "$T/ctl"
	hal_testdev "$@" <"$T/ctl" >"$T/dev.out" 2>&1 &
	TESTDEV_PID=$!
	exec 3>"$T/ctl"
	wait_for "$T/dev.out" ready || exit 1
	node=$(sed -n 's/^ready //p' "$T/dev.out")
}
