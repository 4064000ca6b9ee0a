# lib.sh - sourced by the motion cases' test.sh (cwd: the case directory).
# T: a scratch directory for the case's files (removed at exit; the case directory
#   is the source tree).
# motion_load JOINTS [MOTMOD PARAMS...]: lock-step threads, trivkins, motmod with its
#   two functions on servo-thread, every joint looped back (motor-pos-cmd ->
#   motor-pos-fb, an ideal drive); not started.
# motion_config JOINTS [VEL ACC]: joint and axis limits -100..100, velocity (10),
#   acceleration (100), following error 1 / 0.5 through motcmd.
# motion_coord: enable motion and switch to COORD (trivkins: no homing needed).
# capture_start FILE / capture_stop: halsampler of sampler 0 in the background; the
#   sampler records only between the two (motion_sample leaves it disabled, and
#   capture_stop waits until halsampler has taken every sample), so captures in one
#   test each hold their own periods.
# motion_analyze DT < samples: max |velocity|, max |acceleration| and the final
#   position from positions sampled every period (column 1, scaled by 1e6 so the six
#   printed decimals keep 1e-12 units).
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

motion_load() {
	n=$1
	shift
	halcmd setexact_for_test_suite_only || exit 1
	halcmd loadrt trivkins || exit 1
	halcmd loadrt motmod num_joints=$n "$@" || exit 1
	halcmd addf motion-command-handler servo-thread || exit 1
	halcmd addf motion-controller servo-thread || exit 1
	j=0
	while [ $j -lt $n ]; do
		halcmd net fb$j joint.$j.motor-pos-cmd joint.$j.motor-pos-fb || exit 1
		j=$((j + 1))
	done
}

# sample joint.J.PIN (default pos-cmd) x 1e6 every servo period
motion_sample() {
	halcmd loadrt scale || exit 1
	halcmd loadrt sampler depth=8000 cfg=f || exit 1
	halcmd net sampled joint.$1.${2:-pos-cmd} scale.0.in || exit 1
	halcmd setp scale.0.gain 1000000 || exit 1
	halcmd net scaled scale.0.out sampler.0.pin.0 || exit 1
	halcmd setp sampler.0.enable 0 || exit 1	# capture_start enables it
	halcmd addf scale.0 servo-thread || exit 1
	halcmd addf sampler.0 servo-thread || exit 1
}

motion_config() {
	n=$1 vel=${2:-10} acc=${3:-100}
	: >"$T/config.cmd"
	j=0
	while [ $j -lt $n ]; do
		cat >>"$T/config.cmd" <<CMDS
set-joint-limits $j -100 100
set-joint-vel $j $vel
set-joint-acc $j $acc
set-joint-ferror $j 1
set-joint-min-ferror $j 0.5
CMDS
		j=$((j + 1))
	done
	for l in x y z; do
		cat >>"$T/config.cmd" <<CMDS
set-axis-limits $l -100 100
set-axis-vel $l $vel
set-axis-acc $l $acc
CMDS
	done
	motcmd -f "$T/config.cmd" || exit 1
}

motion_coord() {
	motcmd enable || exit 1
	motcmd coord || exit 1
	motcmd wait-state coord 5 || exit 1
}

capture_start() {
	halsampler >"$1" &
	capture_pid=$!
	halcmd setp sampler.0.enable 1 || exit 1
}

# Stop recording, let halsampler empty the FIFO (curr-depth 0, at most 5 s), then end
# it: nothing is left over for the next capture.
capture_stop() {
	sleep 0.1	# a few more periods at rest
	halcmd setp sampler.0.enable 0 || exit 1
	i=0
	while [ "$(halcmd getp sampler.0.curr-depth)" != 0 ]; do
		i=$((i + 1))
		[ $i -le 100 ] || { echo "capture_stop: halsampler did not empty sampler 0" >&2; exit 1; }
		sleep 0.05
	done
	kill "$capture_pid"
	wait "$capture_pid" 2>/dev/null
}

motion_analyze() {
	awk -v dt="$1" '
	{ p = $1 / 1e6
	  if (n > 0) { v = (p - pp) / dt; av = v < 0 ? -v : v; if (av > vmax) vmax = av
	    if (n > 1) { a = (v - pv) / dt; if (a < 0) a = -a; if (a > amax) amax = a }
	    pv = v }
	  pp = p; n++ }
	END { printf "max-vel %.6f max-acc %.3f final %.6f\n", vmax, amax, pp }'
}
