# SPDX-License-Identifier: GPL-2.0-or-later
# wait-output.sh - sourced (POSIX sh, also the test VM's busybox) by the demo and the
# tests that start a program in the background and wait for a line it prints:
#   wait_output FILE PID SECONDS SEDSCRIPT
# polls FILE every 0.1 s until `sed -n SEDSCRIPT FILE` prints something and prints
# that; returns 1 once process PID has ended or SECONDS have passed without it (the
# caller says what did not come up, and shows FILE).
wait_output() {
	_wo_n=0
	while :; do
		_wo_out=$(sed -n "$4" "$1" 2>/dev/null)
		if [ -n "$_wo_out" ]; then
			echo "$_wo_out"
			return 0
		fi
		_wo_n=$((_wo_n + 1))
		[ $_wo_n -le $(($3 * 10)) ] && kill -0 "$2" 2>/dev/null || return 1
		sleep 0.1
	done
}
