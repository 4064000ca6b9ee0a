#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# make bench: the hot-path figures of issue 20 with their targets (bench/issue20.sh:
# dispatch, halsampler, halcmd start-up, load 64000; BENCH_RUNS runs each, default 5),
# then the three figures of the foundation issue, from the standard workloads of
# bench/gen-workload.sh. Prints numbers; never fails on them.
#   (a) halrun -f wall time for the load workload at N = 1000, 4000, 16000 + growth exponent
#   (b) per-function cost (ns) for the funct workload at N = 1000
#   (c) samples/s halsampler drains from the sample workload with 8 channels, + overruns
#   then stepgen figures, hostmot2 read/write cost on the simulated board, thread wake-up latency (simulated flavor) and the kernel
#   flavor's figures from inside qemu (emulated: behaviour, not speed)
# BENCH_QUICK=1: small workloads, no issue 20, latency or qemu part (the fresh-clone test
# checks with it that the benchmark runs from a clone; its figures mean little).
set -u
build=$(cd "${1:-build}" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
gen=${GEN_WORKLOAD:-$here/gen-workload.sh}
export PATH="$build/bin:$PATH"
quick=${BENCH_QUICK:-0}
if [ "$quick" = 1 ]; then
	load_sizes="100 400 1600" funct_n=100 sample_count=3000
else
	load_sizes="1000 4000 16000" funct_n=1000 sample_count=30000
fi
set -- $load_sizes
n_small=$1 n_mid=$2 n_big=$3
export RTAPI_INSTANCE="bench-$$"
tmp=$(mktemp -d)
trap 'halrun -U >/dev/null 2>&1; rm -rf "$tmp"' EXIT

now() { date +%s.%N; }
calc() { awk "BEGIN { print $* }"; }

if [ "$quick" != 1 ]; then
	"$here/issue20.sh" "$build" "${BENCH_RUNS:-5}"
fi

echo "== (a) config load: halrun -f of the 'load' workload"
declare -A secs
for n in $load_sizes; do
	"$gen" load $n > "$tmp/load-$n.hal"
	t0=$(now)
	if ! halrun -f "$tmp/load-$n.hal" > "$tmp/load-$n.out" 2>&1; then
		echo "N=$n: halrun failed:"; tail -3 "$tmp/load-$n.out"; continue
	fi
	t1=$(now)
	secs[$n]=$(calc "$t1 - $t0")
	printf "N=%-6d %8.3f s\n" $n "${secs[$n]}"
done
if [ -n "${secs[$n_small]:-}" ] && [ -n "${secs[$n_big]:-}" ]; then
	exp=$(calc "log(${secs[$n_big]} / ${secs[$n_small]}) / log(16)")
	printf "growth exponent ($n_small -> $n_big): %.2f  (1 = linear, 2 = quadratic)\n" "$exp"
	exp=$(calc "log(${secs[$n_big]} / ${secs[$n_mid]}) / log(4)")
	printf "growth exponent ($n_mid -> $n_big): %.2f  (includes the fixed start-up of rtapi_app)\n" "$exp"
fi

echo "== (b) per-function cost: 'funct' workload, N=$funct_n, 1 ms thread"
"$gen" funct $funct_n > "$tmp/funct.hal"
if halcmd -f "$tmp/funct.hal" > "$tmp/funct.out" 2>&1; then
	sleep 0.5
	"$build/bin/thread_cost" bench 3
else
	echo "setup failed:"; tail -3 "$tmp/funct.out"
fi
halrun -U >/dev/null 2>&1

echo "== (c) halsampler throughput: 'sample' workload, 8 channels, 100 us thread"
"$gen" sample 8 > "$tmp/sample.hal"
if halcmd -f "$tmp/sample.hal" > "$tmp/sample.out" 2>&1; then
	count=$sample_count
	t0=$(now)
	halsampler -c 0 -n $count > "$tmp/samples.txt" 2> "$tmp/sampler.err"
	t1=$(now)
	lines=$(grep -vc overrun "$tmp/samples.txt")
	overruns=$(grep -c overrun "$tmp/samples.txt" "$tmp/sampler.err" | awk -F: '{s+=$2} END {print s+0}')
	rate=$(calc "$lines / ($t1 - $t0)")
	printf "%d samples in %.2f s: %.0f samples/s drained, %d overrun reports\n" \
		"$lines" "$(calc "$t1 - $t0")" "$rate" "$overruns"
else
	echo "setup failed:"; tail -3 "$tmp/sample.out"
fi
halrun -U >/dev/null 2>&1

echo "== stepgen: maximum step rates and make-pulses cost"
"$build/bin/stepgen_bench"

echo "== kinematics: ns per forward / inverse call of each module"
"$build/bin/kins_bench"

echo "== trajectory planner: cost per cycle, shortest segment reaching feed"
"$build/bin/tp_bench"

echo "== interpreter: RS274NGC blocks per second, generated G1 program (in memory)"
if [ "$quick" = 1 ]; then "$build/bin/interp_bench" 100000; else "$build/bin/interp_bench" 1000000; fi

echo "== motion controller (motmod): cost per servo period with a full look-ahead queue"
"$here/motion-bench.sh" "$build"

echo "== task: sustained queue throughput into motion (generated program of short G1 moves)"
"$here/task-bench.sh" "$build"

echo "== hostmot2: hm2 read + write per cycle, simulated 5i25+7i76 layout (simulated flavor)"
"$here/hostmot2-bench.sh" "$build" 3

echo "== hm2_eth: round trip per servo cycle against the loopback card simulator (simulated flavor)"
"$here/hm2-eth-bench.sh" "$build" "$([ "$quick" = 1 ] && echo 2000 || echo 10000)"

if [ "$quick" = 1 ]; then
	echo "== (BENCH_QUICK: no latency or kernel-flavor figures)"
	exit 0
fi

echo "== latency: thread wake-up error (simulated flavor here; see bench/latency-test.sh for real hardware)"
"$here/latency-test.sh" 5

echo "== kernel flavor inside qemu (EMULATED under TCG: behaviour and scaling only, not speed or latency)"
kver=$(ls /boot 2>/dev/null | sed -n 's/^vmlinuz-\(.*-amd64\)$/\1/p' | grep -v -- -rt- | sort -V | tail -n 1)
if [ -n "$kver" ] && [ -d "/usr/src/linux-headers-$kver" ]; then
	KTEST_BENCH=1 "$here/../tests/kernel/run-kernel-tests.sh" "$kver" 2>&1 | grep '^BENCH' | sed 's/^BENCH /  /'
else
	echo "  skipped: no Debian kernel image/headers (run scripts/kernel-test-deps)"
fi
