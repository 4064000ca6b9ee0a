#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# gen-workload.sh KIND N - prints a .hal file for one of the standard benchmark
# workloads (bench/run-bench.sh, tests/kernel/run-kernel-tests.sh KTEST_BENCH=1).
# The same files can be run against other HAL implementations, so the figures
# compare like with like.
#   load N   : N and2 instances, N signals in a ring, N setp, N addf (config-load scaling)
#   funct N  : as load, on a 1 ms thread, started (per-function overhead)
#   sample N : a 100 us thread feeding N float channels into sampler 0 (halsampler throughput)
#   fill N   : a 20 us thread feeding N float channels into a 100,000-deep sampler 0, to be
#              stopped once full and drained with halsampler -n 99000 (halsampler CPU cost)
set -eu
kind=${1:?usage: gen-workload.sh load|funct|sample|fill N}
n=${2:?usage: gen-workload.sh load|funct|sample|fill N}
case $n in '' | *[!0-9]* | 0) echo "gen-workload.sh: N must be a positive number, not '$n'" >&2; exit 2 ;; esac
case $kind in
load | funct)
	echo "loadrt threads name1=bench period1=1000000"
	echo "loadrt and2 count=$n"
	for ((i = 0; i < n; i++)); do
		echo "net ring-$i and2.$i.out => and2.$(((i + 1) % n)).in0"
		echo "setp and2.$i.in1 1"
		echo "addf and2.$i bench"
	done
	if [ "$kind" = funct ]; then echo "start"; fi
	;;
sample | fill)
	cfg=$(printf 'f%.0s' $(seq 1 "$n"))
	if [ "$kind" = fill ]; then period=20000 depth=100000; else period=100000 depth=65536; fi
	echo "loadrt threads name1=fast period1=$period"
	echo "loadrt siggen num_chan=1"
	echo "loadrt sampler cfg=$cfg depth=$depth"
	pins=""
	for ((i = 0; i < n; i++)); do pins="$pins sampler.0.pin.$i"; done
	echo "net sine siggen.0.sine =>$pins"
	echo "addf siggen.0.update fast"
	echo "addf sampler.0 fast"
	echo "start"
	;;
*) echo "gen-workload.sh: unknown kind '$kind' (load, funct, sample or fill)" >&2; exit 2 ;;
esac
