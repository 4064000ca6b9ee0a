# lib.sh - sourced by the task cases' test.sh (cwd: the case directory).
# T: scratch directory with a copy of common/sim.ini and sim.tbl (the parameter file
#    and the tool table are written there). BUS: the bus socket. INI: the INI copy.
# task_start [HALFILE]: motion (common/machine.hal), io, loop-backs (unless the case
#    gives its own HAL file for them), milltask; threads started.
# bus CMD...: emcbus on the test's bus.
# machine_ready: estop reset, machine on, home all, into MDI mode.
# Other suites (tests/halui, tests/emcrsh) source it too: TASK_COMMON names this
# directory's common/ from their case directories, MACHINE_INI another INI to copy.
TASK_COMMON=${TASK_COMMON:-../common}
MACHINE_INI=${MACHINE_INI:-$TASK_COMMON/sim.ini}
T=$(mktemp -d "${TEST_TMPDIR:-/tmp}/task.XXXXXX")
trap 'rm -rf "$T"' EXIT
INI=$T/sim.ini
BUS=$T/bus.sock
cp "$MACHINE_INI" "$T/sim.ini" || exit 1
cp "$TASK_COMMON/sim.tbl" "$T"/ || exit 1

bus() {
	emcbus -bus "$BUS" "$@"
}

task_start() {
	halcmd setexact_for_test_suite_only || exit 1
	halcmd -f "$TASK_COMMON/machine.hal" || exit 1
	halcmd loadusr -Wn iocontrol io -ini "$INI" -bus "$BUS" || exit 1
	if [ -n "$1" ]; then
		halcmd -f "$1" || exit 1
	else
		halcmd net estop-loop iocontrol.0.user-enable-out iocontrol.0.emc-enable-in || exit 1
		halcmd net tool-prep-loop iocontrol.0.tool-prepare iocontrol.0.tool-prepared || exit 1
		halcmd net tool-change-loop iocontrol.0.tool-change iocontrol.0.tool-changed || exit 1
	fi
	halcmd start || exit 1
	halcmd loadusr -Wn inihal milltask -ini "$INI" -bus "$BUS" || exit 1
	bus wait task.motion_ready 1 10 || exit 1
	bus wait io.connected 1 10 || exit 1
}

machine_ready() {
	bus state estop_reset || exit 1
	bus state on || exit 1
	bus mode manual || exit 1
	bus home -1 || exit 1
	bus wait traj.all_homed 1 10 || exit 1
	bus mode mdi || exit 1
}

# positions of the three joints, 3 decimals
joints() {
	printf 'joints %.3f %.3f %.3f\n' "$(halcmd getp joint.0.pos-cmd)" "$(halcmd getp joint.1.pos-cmd)" \
		"$(halcmd getp joint.2.pos-cmd)"
}

task_stop() {
	halcmd unloadusr iocontrol
	halcmd unloadusr inihal
	halrun -U
}

# sample joints 0..2 every servo period (halsampler, in the background) into FILE
sample_start() {
	halcmd loadrt sampler depth=20000 cfg=fff || exit 1
	halcmd net j0 sampler.0.pin.0 || exit 1
	halcmd net j1 sampler.0.pin.1 || exit 1
	halcmd net j2 sampler.0.pin.2 || exit 1
	halcmd addf sampler.0 servo-thread || exit 1
	halsampler >"$1" &
	sampler_pid=$!
}

sample_stop() {
	sleep 0.1
	kill "$sampler_pid"
	wait "$sampler_pid" 2>/dev/null
}
