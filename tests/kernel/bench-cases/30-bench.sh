#!/bin/sh
# Kernel-flavor benchmark figures inside qemu (TCG): EMULATED, so they show that
# the workloads run and how they scale, not real speed or latency. Lines start
# with BENCH; bench/run-bench.sh prints them.
export HAL_FLAVOR=kernel RTAPI_INSTANCE=bench
now() { cut -d' ' -f1 /proc/uptime; }
for n in 1000 4000 16000; do
	t0=$(now)
	halrun -f /bench/load-$n.hal >/tmp/load.out 2>&1 || { echo "BENCH load N=$n failed: $(tail -n 1 /tmp/load.out)"; continue; }
	echo "BENCH load N=$n: $(awk -v a="$t0" -v b="$(now)" 'BEGIN { printf "%.2f", b - a }') s (emulated)"
done
halcmd -f /bench/funct-1000.hal >/tmp/funct.out 2>&1 || echo "BENCH funct setup failed: $(tail -n 1 /tmp/funct.out)"
sleep 1
echo "BENCH funct N=1000: $(thread_cost bench 3 2>&1) (emulated)"
# issue 20's dispatch figure: thread Time / functions, in the (emulated) TSC's clocks
echo "BENCH dispatch funct N=1000: $(dispatch_cost bench 2 2>&1) (emulated)"
halrun -U >/dev/null 2>&1
halcmd -f /bench/sample-8.hal >/tmp/sample.out 2>&1 || echo "BENCH sample setup failed: $(tail -n 1 /tmp/sample.out)"
t0=$(now)
halsampler -c 0 -n 5000 >/tmp/samples.txt 2>&1 || echo "BENCH halsampler failed: $(tail -n 1 /tmp/samples.txt)"
lines=$(grep -vc overrun /tmp/samples.txt || true)
over=$(grep -c overrun /tmp/samples.txt || true)
echo "BENCH sample 8 channels: $lines samples in $(awk -v a="$t0" -v b="$(now)" 'BEGIN { printf "%.2f", b - a }') s, $over overrun reports (emulated)"
halrun -U >/dev/null 2>&1
true
