#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# motion-bench.sh [BUILD] - motmod's controller cost per servo period: a simulated
# three-joint machine (trivkins, 1 ms servo thread) is paused, its queue filled with
# N short G64 segments (0.05 mm at 3 m/min, one segment per period), then resumed;
# sampler records motion-command-handler.time + motion-controller.time every period
# while the look-ahead queue is full. Prints the median and maximum in µs (CPU clocks
# converted with motion.servo.last-period, the clocks of one 1 ms period), and
# whether the segments kept the programmed feed. Figures only; never fails on them.
set -u
build=$(cd "${1:-build}" && pwd)
export PATH="$build/bin:$PATH"
export RTAPI_INSTANCE="motbench-$$"
n=${MOTION_BENCH_SEGMENTS:-900}	# + a blend arc at each junction: ~1800 queued
samples=${MOTION_BENCH_SAMPLES:-600}
tmp=$(mktemp -d)
trap 'halrun -U >/dev/null 2>&1; rm -rf "$tmp"' EXIT
halrun -U >/dev/null 2>&1
halcmd loadrt trivkins &&
halcmd loadrt motmod num_joints=3 &&
halcmd loadrt sampler depth=$((samples + 100)) cfg=ssf &&
halcmd addf motion-command-handler servo-thread &&
halcmd addf motion-controller servo-thread &&
halcmd addf sampler.0 servo-thread &&
halcmd net t1 motion-command-handler.time sampler.0.pin.0 &&
halcmd net t2 motion-controller.time sampler.0.pin.1 &&
halcmd net v motion.current-vel sampler.0.pin.2 &&
halcmd setp sampler.0.enable 0 || { echo "motion-bench: HAL setup failed"; exit 1; }
for j in 0 1 2; do
	halcmd net fb$j joint.$j.motor-pos-cmd joint.$j.motor-pos-fb || exit 1
done
halcmd start || exit 1
{
	for j in 0 1 2; do
		echo "set-joint-limits $j -1000 1000"; echo "set-joint-vel $j 200"; echo "set-joint-acc $j 2000"
		echo "set-joint-ferror $j 10"; echo "set-joint-min-ferror $j 10"
	done
	for l in x y z; do
		echo "set-axis-limits $l -1000 1000"; echo "set-axis-vel $l 200"; echo "set-axis-acc $l 2000"
	done
	echo "enable"; echo "coord"; echo "wait-state coord 5"; echo "term-cond blend 0.01"; echo "pause"
	# a gentle zig-zag along X: short segments, nearly tangent junctions
	awk -v n="$n" 'BEGIN { for (i = 1; i <= n; i++)
		printf "line %.4f %.6f 0 50 2000\n", i * 0.05, (i % 2) * 0.0005 }'
} >"$tmp/cmds"
start=$(date +%s.%N)
motcmd -f "$tmp/cmds" >"$tmp/out" 2>&1 || { echo "motion-bench: queueing failed:"; tail -3 "$tmp/out"; exit 1; }
queued=$(motcmd status | awk '/^queue/ { print $3 }')
clocks=$(halcmd getp motion.servo.last-period)
halcmd setp sampler.0.enable 1
motcmd resume || exit 1
halsampler -n "$samples" >"$tmp/samples" || exit 1
motcmd wait-inpos 60 >/dev/null
echo "== motion (motmod): $n segments of 0.05 mm at 50 mm/s (3 m/min), G64 P0.01, 1 ms servo period"
echo "queued before resume: $queued segments (queueing took $(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }') s)"
awk -v clocks="$clocks" '{ printf "%.3f\n", ($1 + $2) / (clocks / 1000.0) }' "$tmp/samples" |
	sort -n >"$tmp/us"
periods=$(grep -c . "$tmp/us")
printf "motion-command-handler + motion-controller per period: median %s us, max %s us (%d periods, %s clocks per ms)\n" \
	"$(sed -n "$(((periods + 1) / 2))p" "$tmp/us")" "$(tail -1 "$tmp/us")" "$periods" "$clocks"
awk '{ if ($3 > vmax) vmax = $3; if (NR > 100 && NR < 500) { vs += $3; vn++ } }
	END { printf "path speed: max %.2f mm/s, mean over periods 100-500 %.2f mm/s (programmed 50)\n", vmax, vn ? vs / vn : 0 }' \
	"$tmp/samples"
