# lib.sh - sourced by the motion-tp cases' test.sh (cwd: the case directory), on top
# of ../motion/lib.sh (motion_load, motion_config, capture_start/stop).
# tp_sample: joints 0 and 1 (X and Y, trivkins) pos-cmd x 1e6 into sampler 0,
#   every servo period.
# tp_square_run FILE TERM [TOL]: COORD mode, the 5 x 5 square at F 8 under
#   term-cond TERM, captured into FILE (in the scratch directory $T).
# tp_analyze DT VMAX AMAX TOL < samples: per-axis velocity/acceleration limits, the
#   distance from the programmed square, whether it stopped on each corner (a sample
#   within 2e-5 of it at a speed below 2 a dt), the final point
#   (tests/helpers/motion_pathcheck.cpp: busybox awk in the VM has no sqrt).
. ../../motion/lib.sh
# scratch files: motion/lib.sh's $T if it has one, else a directory of our own
if [ -z "${T:-}" ]; then
	T=$(mktemp -d)
	trap 'rm -rf "$T"' EXIT
fi

tp_sample() {
	halcmd loadrt scale count=2 || exit 1
	halcmd loadrt sampler depth=16000 cfg=ff || exit 1
	for j in 0 1; do
		halcmd net sampled$j joint.$j.pos-cmd scale.$j.in || exit 1
		halcmd setp scale.$j.gain 1000000 || exit 1
		halcmd net scaled$j scale.$j.out sampler.0.pin.$j || exit 1
		halcmd addf scale.$j servo-thread || exit 1
	done
	halcmd addf sampler.0 servo-thread || exit 1
}

tp_square_run() {
	motcmd enable || exit 1
	motcmd coord || exit 1
	motcmd wait-state coord 10 || exit 1
	motcmd term-cond "$2" $3 || exit 1
	capture_start "$1"
	cat >"$T/square.cmd" <<CMDS
line 5 0 0 8 100
line 5 5 0 8 100
line 0 5 0 8 100
line 0 0 0 8 100
CMDS
	motcmd -f "$T/square.cmd" || exit 1
	sleep 0.2
	motcmd wait-inpos 30 || exit 1
	capture_stop
}

tp_analyze() {
	motion_pathcheck square "$@"
}
