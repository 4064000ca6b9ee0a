#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# issue20.sh BUILD_DIR [RUNS]: the four hot-path figures of issue 20, each with its
# target, simulated flavor, median and max of RUNS runs (default 5). Prints figures,
# never fails on them ("met" / "NOT met" is information, not a test result).
#   dispatch   : funct 1000 workload, thread Time / 1000 functions (CPU clocks), and
#                the thread's Max-Time over the same window against the median
#   halsampler : fill 8 workload (100,000-deep FIFO at 20 us), stopped when full, then
#                CPU time of "halsampler -n 99000" per sample
#   halcmd     : CPU time of "halcmd -f" of a 10-line file against the running funct 1000 session
#   load       : halrun -f of the load workload at N = 16000, 32000, 48000, 64000 (wall time)
set -u
build=$(cd "${1:-build}" && pwd)
runs=${2:-5}
here=$(cd "$(dirname "$0")" && pwd)
gen=${GEN_WORKLOAD:-$here/gen-workload.sh}
export PATH="$build/bin:$PATH"
export RTAPI_INSTANCE="bench20-$$"
tmp=$(mktemp -d)
trap 'halrun -U >/dev/null 2>&1; rm -rf "$tmp"' EXIT

# median and max of numbers on stdin, one per line: "MEDIAN MAX"
stats() { sort -g | awk '{ v[NR] = $1 } END { if (NR) printf "%s %s\n", v[int((NR + 1) / 2)], v[NR] }'; }
verdict() { awk "BEGIN { print ($1) ? \"met\" : \"NOT met\" }"; }

echo "== issue 20: hot paths (simulated flavor; median and max of $runs runs)"

# --- dispatch -------------------------------------------------------------------
"$gen" funct 1000 > "$tmp/funct.hal"
if halcmd -f "$tmp/funct.hal" > "$tmp/funct.out" 2>&1; then
	sleep 1
	: > "$tmp/med"; : > "$tmp/ratio"
	for ((r = 0; r < runs; r++)); do
		line=$(dispatch_cost bench 2) || continue
		# "... median M, max X clocks per function (thread tmax T per function, Rx the median)"
		echo "$line" | sed -n 's/.*median \([0-9.]*\),.*/\1/p' >> "$tmp/med"
		echo "$line" | sed -n 's/.*, \([0-9.]*\)x the median.*/\1/p' >> "$tmp/ratio"
	done
	read -r med medmax < <(stats < "$tmp/med")
	read -r ratio ratiomax < <(stats < "$tmp/ratio")
	floor=$(clock_floor)
	printf "dispatch (funct 1000): %s clocks per function (max of the run medians %s); target <= 15: %s\n" \
		"$med" "$medmax" "$(verdict "$med <= 15")"
	printf "  thread Max-Time over 2 s: %sx the median (worst run %sx); target <= 2x: %s\n" \
		"$ratio" "$ratiomax" "$(verdict "$ratio <= 2")"
	printf "  one clock read (TSC) costs %s clocks back to back on this CPU: the floor with every function timed\n" "$floor"
	# --- halcmd start-up, against this running session ----------------------------
	cat > "$tmp/ten.hal" <<'HAL'
# ten lines against a running session
setp and2.0.in1 1
setp and2.1.in1 1
getp and2.0.in1
newsig ten-a bit
sets ten-a 1
net ten-a and2.3.in1
show pin and2.0
unlinkp and2.3.in1
delsig ten-a
HAL
	: > "$tmp/cpu"; : > "$tmp/wall"
	for ((r = 0; r < 4 * runs; r++)); do
		read -r cpu wall < <(cpu_time halcmd -f "$tmp/ten.hal") || continue
		awk "BEGIN { print $cpu * 1000 }" >> "$tmp/cpu"
		awk "BEGIN { print $wall * 1000 }" >> "$tmp/wall"
	done
	read -r cmed cmax < <(stats < "$tmp/cpu")
	read -r wmed wmax < <(stats < "$tmp/wall")
	printf "halcmd -f (10 lines, running funct 1000 session): %.1f ms CPU (max %.1f), %.1f ms wall (max %.1f); target <= 15 ms: %s\n" \
		"$cmed" "$cmax" "$wmed" "$wmax" "$(verdict "$cmed <= 15")"
else
	echo "dispatch: setup failed:"; tail -3 "$tmp/funct.out"
fi
halrun -U >/dev/null 2>&1

# --- halsampler ----------------------------------------------------------------
"$gen" fill 8 > "$tmp/fill.hal"
: > "$tmp/us"; : > "$tmp/sums"
for ((r = 0; r < runs; r++)); do
	if ! halcmd -f "$tmp/fill.hal" > "$tmp/fill.out" 2>&1; then
		echo "halsampler: setup failed:"; tail -3 "$tmp/fill.out"; break
	fi
	for ((i = 0; i < 300; i++)); do
		d=$(halcmd getp sampler.0.curr-depth 2>/dev/null || echo 0)
		[ "$d" -ge 99000 ] && break
		sleep 0.1
	done
	halcmd stop
	if read -r cpu wall < <(cpu_time -o "$tmp/samples.txt" halsampler -n 99000); then
		awk "BEGIN { print $cpu / 99000 * 1e6 }" >> "$tmp/us"
		md5sum < "$tmp/samples.txt" >> "$tmp/sums"
	fi
	halrun -U >/dev/null 2>&1
done
read -r smed smax < <(stats < "$tmp/us")
same=$(sort -u "$tmp/sums" | wc -l)
printf "halsampler -n 99000 (fill 8): %.3f us CPU per sample (max %.3f); target <= 0.45: %s; output %s\n" \
	"$smed" "$smax" "$(verdict "$smed <= 0.45")" \
	"$([ "$same" = 1 ] && echo "identical in every run" || echo "DIFFERS between runs")"

# --- load ------------------------------------------------------------------------
# 64000 two-input components with their nets need about 100 MB of HAL records: more
# than the default 64 MiB segment holds (~59,000), so every load run asks for 128 MiB
# (HAL_SIZE: README, halcmd(1)); the same size for every N keeps the growth figure fair.
export HAL_SIZE=128M
declare -A lmed
for n in 16000 32000 48000 64000; do
	"$gen" load $n > "$tmp/load-$n.hal"
	: > "$tmp/lw"
	for ((r = 0; r < (n == 64000 ? runs : 2); r++)); do
		if read -r cpu wall < <(cpu_time -o "$tmp/load.out" halrun -f "$tmp/load-$n.hal" 2> "$tmp/load.err"); then
			echo "$wall" >> "$tmp/lw"
		else
			halrun -U >/dev/null 2>&1
			printf "load %-5d (%d objects): failed: %s\n" $n $((4 * n)) \
				"$(grep -v '^cpu_time' "$tmp/load.err" | grep -v 'missed .* periods\|missed 1 period' | tail -1)"
			break
		fi
	done
	[ -s "$tmp/lw" ] || continue
	read -r m x < <(stats < "$tmp/lw")
	lmed[$n]=$m
	printf "load %-5d (%d objects): %.3f s (max %.3f)%s\n" $n $((4 * n)) "$m" "$x" \
		"$([ $n = 64000 ] && echo "; target < 1 s: $(verdict "$m < 1") (HAL_SIZE=$HAL_SIZE)")"
done
for big in 64000 48000; do
	if [ -n "${lmed[16000]:-}" ] && [ -n "${lmed[$big]:-}" ]; then
		printf "  growth exponent 16000 -> %d: %.2f (1 = linear)\n" $big \
			"$(awk "BEGIN { print log(${lmed[$big]} / ${lmed[16000]}) / log($big / 16000) }")"
		break
	fi
done
