#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# drive-emcrsh.sh - the demo's drive step through emcrsh(1), the text-mode control
# server: each step starts "emcrsh -p 0 -- -ini INI" on a free port and talks to it
# as a telnet user would (tests/helpers/rsh_client carries the lines): log in, take
# the enable, send the SET commands, poll with GET until the machine is there, and
# end the server with SHUTDOWN. Same steps and exit codes as drive-emcbus.sh:
#   drive-emcrsh.sh home INI          estop off, machine on, home all, wait until homed
#   drive-emcrsh.sh run INI PROGRAM   auto mode, open PROGRAM, run it, wait for its end
# Exit 0 when done; 1 after a one-line message naming the step that failed
# (emcrsh's GET ERROR text with it where task refused something).
set -u
step=${1:-}
ini=${2:-}
if [ "$step" = --until ] && [ $# -eq 5 ]; then
	# --until PORT SECONDS GETLINE REPLY: poll every 0.2 s on a fresh connection
	n=0
	while :; do
		last=$(printf 'hello EMC demo 1.0\nset echo off\n%s\n' "$4" | rsh_client -t 30 127.0.0.1 "$2" |
			sed 's/\\[rn]//g' | tail -1)
		echo "$last" | grep -q "^$5\$" && exit 0
		n=$((n + 1))
		[ $n -le $(($3 * 5)) ] || break
		sleep 0.2
	done
	echo "drive-emcrsh: timed out after $3 s waiting for '$4' to answer '$5' (last: $last)"
	exit 1
fi
case $step in
home) [ $# -eq 2 ] ;;
run) [ $# -eq 3 ] ;;
*) false ;;
esac || { echo "usage: drive-emcrsh.sh home INI | run INI PROGRAM" >&2; exit 2; }

tmp=$(mktemp -d "${TMPDIR:-/tmp}/drive-emcrsh.XXXXXX") || exit 1
rsh_pid=
cleanup() {
	# (the shell's "Terminated" report of the killed server is not news)
	[ -z "$rsh_pid" ] || { kill -TERM "$rsh_pid"; wait "$rsh_pid"; } 2>/dev/null
	rm -rf "$tmp"
}
trap cleanup EXIT
fail() {
	echo "drive-emcrsh: $*" >&2
	exit 1
}

: > "$tmp/server.log"
emcrsh -p 0 -- -ini "$ini" > "$tmp/server.log" 2>&1 < /dev/null &
rsh_pid=$!
. "$(dirname "$0")/wait-output.sh"
port=$(wait_output "$tmp/server.log" "$rsh_pid" 30 's/^emcrsh: listening on port \([0-9]*\)$/\1/p') || {
	sed 's/^/  emcrsh: /' "$tmp/server.log" >&2
	fail "emcrsh did not start"
}

# session - one connection: log in, take the enable, every SET waits until task has
# done it; then the lines on stdin (rsh_client's "!sh CMD" runs CMD at that point).
# Prints the replies, one per line (their line ends dropped).
session() {
	{
		echo "hello EMC demo 1.0"
		echo "set echo off"
		echo "set enable EMCTOO"
		echo "set set_wait done"
		echo "set timeout 120"
		cat
	} | rsh_client -t 400 127.0.0.1 "$port" > "$tmp/reply" 2>&1 || {
		sed 's/\\[rn]//g' "$tmp/reply" >&2
		fail "no answer from emcrsh on port $port"
	}
	sed 's/\\[rn]//g' "$tmp/reply"
}
# steps LINE... - one session, GET ERROR after each line: the first NAK, wait that
# timed out or error task reported fails the step with task's text
steps() {
	r=$(for l in "$@"; do echo "$l"; echo "get error"; done | session) || exit 1
	bad=$(echo "$r" | awk -v q="'" '
		/NAK|^drive-emcrsh:/ && what == "" { what = $0; next }
		/^ERROR / && $0 != "ERROR OK" && text == "" { text = substr($0, 7) }
		END { if (what != "") print q what q ": " (text != "" ? text : "no error text")
		      else if (text != "") print "task reported: " text }')
	[ -z "$bad" ] || fail "$bad"
}

# The waits run inside the session (rsh_client's !sh, in the script's order) so its
# connection sees task's error messages while the machine moves; they poll on
# connections of their own: drive-emcrsh.sh --until PORT SECONDS GETLINE REPLY
# (REPLY: a basic regular expression the whole reply line must match).
self=$(cd "$(dirname "$0")" && pwd)/$(basename "$0")
wait_for() {
	echo "!sh '$self' --until $port $1 '$2' '$3'"
}
case $step in
home)
	steps "set mode manual" "set estop off" "set machine on" "set home -1" \
		"$(wait_for 120 'get joint_homed' 'JOINT_HOMED\( YES\)\{1,\}')"
	;;
run)
	# SET RUN (SET_WAIT DONE) returns once task has started the program; the status may
	# show it a moment later (a program that fails at once never shows RUNNING)
	steps "set mode auto" "set open $3" "set run" \
		"!sh '$self' --until $port 2 'get program_status' 'PROGRAM_STATUS RUNNING' > /dev/null" \
		"$(wait_for 300 'get program_status' 'PROGRAM_STATUS IDLE')"
	;;
esac
echo shutdown | session > /dev/null
wait "$rsh_pid"
rc=$?
rsh_pid=
[ $rc -eq 0 ] || fail "emcrsh exited with status $rc after SHUTDOWN"
exit 0
