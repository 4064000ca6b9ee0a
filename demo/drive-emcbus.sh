#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# drive-emcbus.sh - the demo's drive step: the commands a client sends to the running
# machine, here through task's bus with emcbus(1). Nothing else in demo/ knows how the
# machine is driven: another client (emcrsh, halui) replaces this one file.
#   drive-emcbus.sh home INI          estop reset, machine on, Home All, wait until homed
#   drive-emcbus.sh run INI PROGRAM   auto mode, open PROGRAM, run it, wait for its end
# Exit 0 when done; otherwise 1 after a one-line message naming the step (emcbus
# prints task's own reason above it).
set -u
step=${1:-}
ini=${2:-}
bus() {
	emcbus -ini "$ini" "$@" || { echo "drive-emcbus: 'emcbus $*' failed" >&2; exit 1; }
}
case $step in
home)
	bus STATE ESTOP_RESET
	bus STATE ON
	bus MODE MANUAL
	bus HOME -1
	bus wait traj.all_homed 1 120
	;;
run)
	[ $# -eq 3 ] || { echo "usage: drive-emcbus.sh run INI PROGRAM" >&2; exit 2; }
	bus MODE AUTO
	bus OPEN "$3"
	bus RUN
	sleep 0.5	# task reports the running program from its next cycle on
	bus wait task.interp IDLE 300
	err=$(bus status task.last_error)
	[ -z "$err" ] || { echo "drive-emcbus: the program stopped: $err" >&2; exit 1; }
	;;
*)
	echo "usage: drive-emcbus.sh home INI | run INI PROGRAM" >&2
	exit 2
	;;
esac
