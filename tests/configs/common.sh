# Shared by the tests/configs cases (POSIX sh). A configuration is checked twice:
#  hal_check: its HAL files loaded as the launcher loads them (halcmd -i INI -f FILE),
#    what task would send from the INI ([JOINT_n], [AXIS_L], [TRAJ]) given through
#    motcmd, then Home All: every joint must end homed at its [JOINT_n]HOME.
#  launch_check: "emc INI" with [TASK]TASK and [EMCIO]EMCIO as configured (milltask,
#    io): skipped, with the reason, when those programs are not built.
. ../../../demo/wait-output.sh
T=${TEST_TMPDIR:-/tmp}
CONFIGS=$(cd ../../../configs/sim && pwd)
export EMC_LOCK_FILE="$T/emc.lock" EMC_RC_FILE="$T/emcrc"

# ini_cmds INI JOINTS LETTERS: the motcmd lines task would send, made by halcmd's own
# [SECTION]KEY substitution (a missing key is an error naming it).
ini_cmds() {
	ini=$1 joints=$2 letters=$3
	{
		j=0
		while [ $j -lt "$joints" ]; do
			echo "echo set-joint-limits $j [JOINT_$j]MIN_LIMIT [JOINT_$j]MAX_LIMIT"
			echo "echo set-joint-vel $j [JOINT_$j]MAX_VELOCITY"
			echo "echo set-joint-acc $j [JOINT_$j]MAX_ACCELERATION"
			echo "echo set-joint-ferror $j [JOINT_$j]FERROR"
			echo "echo set-joint-min-ferror $j [JOINT_$j]MIN_FERROR"
			echo "echo set-joint-homing $j [JOINT_$j]HOME_OFFSET [JOINT_$j]HOME [JOINT_$j]HOME_FINAL_VEL [JOINT_$j]HOME_SEARCH_VEL [JOINT_$j]HOME_LATCH_VEL 0 [JOINT_$j]HOME_SEQUENCE"
			j=$((j + 1))
		done
		for l in $letters; do
			echo "echo set-axis-limits $l [AXIS_$l]MIN_LIMIT [AXIS_$l]MAX_LIMIT"
			echo "echo set-axis-vel $l [AXIS_$l]MAX_VELOCITY"
			echo "echo set-axis-acc $l [AXIS_$l]MAX_ACCELERATION"
		done
		echo "echo set-vel-limit [TRAJ]MAX_LINEAR_VELOCITY"
		echo "echo set-acc [TRAJ]MAX_LINEAR_ACCELERATION"
	} > "$T/gen.hal"
	halcmd -i "$ini" -f "$T/gen.hal"
}

# hal_check NAME JOINTS LETTERS HALFILE...: load, home, print each joint's state.
hal_check() {
	name=$1 joints=$2 letters=$3
	shift 3
	ini=$CONFIGS/$name.ini
	(
		cd "$CONFIGS" || exit 1
		halcmd setexact_for_test_suite_only || exit 1
		for f in "$@"; do
			halcmd -i "$ini" -f "$f" || exit 1
		done
		halcmd start || exit 1
		ini_cmds "$ini" "$joints" "$letters" > "$T/machine.cmd" || exit 1
		motcmd -f "$T/machine.cmd" || exit 1
		motcmd enable || exit 1
		motcmd wait-state free 5 || exit 1
		motcmd home all || exit 1
		motcmd wait-homed 120 || exit 1
		motcmd wait-inpos 30 || exit 1
		j=0
		while [ $j -lt "$joints" ]; do
			home=$(echo "echo [JOINT_$j]HOME" | halcmd -i "$ini" -f)
			printf 'joint %d homed %s pos-fb %.3f HOME %.3f motor-offset %.2f\n' $j \
				"$(halcmd getp joint.$j.homed)" "$(halcmd getp joint.$j.pos-fb)" "$home" \
				"$(halcmd getp joint.$j.motor-offset)"
			j=$((j + 1))
		done
		motcmd errors
	)
	status=$?
	halrun -U
	return $status
}

# launch_check NAME: the whole machine through the launcher, headless, from a copy of
# configs/sim (task writes the parameter file beside the INI): which components came
# up, then through task's bus (emcbus): estop reset, machine on, Home All, the sample
# program NAME.ngc run to its end; then SIGTERM, and nothing may be left.
launch_check() {
	name=$1
	for prog in milltask io emcbus; do
		if ! command -v $prog > /dev/null 2>&1; then
			echo "launch: $prog failed: not on PATH (the build makes it)"
			return 1
		fi
	done
	rm -rf "$T/cfg"
	cp -r "$CONFIGS" "$T/cfg"
	ini=$T/cfg/$name.ini
	: > "$T/emc.out"	# exists before the wait below reads it
	emc -v "$ini" > "$T/emc.out" 2>&1 < /dev/null &
	pid=$!
	if ! wait_output "$T/emc.out" $pid 60 '/running headless/p' > /dev/null; then
		echo "launch: did not come up"
		cat "$T/emc.out"
		kill -TERM $pid 2>/dev/null
		wait $pid
		return 1
	fi
	echo "launch: comps $(halcmd show comp | sed -n 's/^ *[0-9][0-9]* *[RTUser]* *\([^ ]*\).*/\1/p' | sort | tr '\n' ' ')"
	bus() {
		if ! out=$(emcbus -ini "$ini" "$@" 2>&1); then
			echo "launch: emcbus $* failed: $out"
		fi
	}
	bus STATE ESTOP_RESET
	bus STATE ON
	bus MODE MANUAL
	bus HOME -1
	bus wait traj.all_homed 1 120
	echo "launch: homed $(emcbus -ini "$ini" status traj.all_homed)"
	bus MODE AUTO
	bus OPEN "$T/cfg/$name.ngc"
	bus RUN
	sleep 0.5
	bus wait task.interp IDLE 300
	echo "launch: program ended, last error '$(emcbus -ini "$ini" status task.last_error)'"
	kill -TERM $pid
	wait $pid
	echo "launch: exit $?"
	if [ "$HAL_TEST_FLAVOR" = kernel ]; then
		echo "launch: left $(grep -c '^hal_lib ' /proc/modules)"
	else
		echo "launch: left $(ls /dev/shm | grep -c -- "-${RTAPI_INSTANCE:-0}-")"
	fi
}
