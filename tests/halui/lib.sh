# lib.sh - sourced by the halui cases' test.sh (cwd: the case directory).
# The simulated mill of tests/task (tests/task/lib.sh: motmod + io + milltask, with
# this directory's common/sim.ini, which adds [HALUI], instead of tests/task's) plus halui from the same INI
# file; everything is then driven through halui's pins with halcmd setp.
# machine_start: task_start, then halui.   machine_stop: halui, then task_stop.
# pin NAME: halcmd getp halui.NAME
# press NAME: halui.NAME TRUE long enough for halui's 50 Hz loop to see it, then FALSE.
# wait_pin NAME VALUE [SECONDS]: until halui.NAME reads VALUE (else a message, exit 1).
TASK_COMMON=../../task/common MACHINE_INI=../common/sim.ini
. ../../task/lib.sh

pin() {
	halcmd getp "halui.$1"
}

press() {
	halcmd setp "halui.$1" 1 || exit 1
	sleep 0.3
	halcmd setp "halui.$1" 0 || exit 1
	sleep 0.05
}

wait_pin() {
	n=0
	limit=$(( ${3:-10} * 20 ))
	while [ "$(pin "$1")" != "$2" ]; do
		n=$((n + 1))
		if [ $n -gt $limit ]; then
			echo "halui.$1 is $(pin "$1"), not $2, after ${3:-10} s"
			exit 1
		fi
		sleep 0.05
	done
}

machine_start() {
	task_start
	halcmd loadusr -Wn halui halui -ini "$INI" -bus "$BUS" || exit 1
}

# estop reset, machine on, home all, through halui's pins
machine_on() {
	press estop.reset
	wait_pin estop.is-activated FALSE
	press machine.on
	wait_pin machine.is-on TRUE
	press mode.manual
	press home-all
	bus wait traj.all_homed 1 10 || exit 1
}

machine_stop() {
	halcmd unloadusr halui
	task_stop
}
