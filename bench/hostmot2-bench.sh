#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# hostmot2-bench.sh BUILD_DIR [SECONDS]: cost of hm2 read + write per cycle for a
# 5i25+7i76-sized layout (34 IO pins, 5 stepgens enabled and moving, 1 encoder,
# 1 pwmgen, watchdog, DPLL) on the simulated board, simulated flavor, 1 ms thread:
# CPU time of the two functions per cycle (including the register model, which
# stands in for the PCI/Ethernet transfer) and 32-bit bus words moved per cycle.
set -u
build=$(cd "${1:-build}" && pwd)
secs=${2:-3}
export PATH="$build/bin:$PATH"
export RTAPI_INSTANCE="hm2bench-$$"
trap 'halrun -U >/dev/null 2>&1' EXIT
tmp=$(mktemp -d)
cat > "$tmp/hm2.hal" <<'HAL'
loadrt threads name1=hm2 period1=1000000
loadrt hostmot2
loadrt hm2_sim board=5i25
loadrt sampler depth=200 cfg=u
setp hm2_5i25.0.watchdog.timeout_ns 1000000000
setp hm2_5i25.0.stepgen.00.enable TRUE
setp hm2_5i25.0.stepgen.01.enable TRUE
setp hm2_5i25.0.stepgen.02.enable TRUE
setp hm2_5i25.0.stepgen.03.enable TRUE
setp hm2_5i25.0.stepgen.04.enable TRUE
setp hm2_5i25.0.stepgen.00.control-type TRUE
setp hm2_5i25.0.stepgen.00.velocity-cmd 100
setp hm2_5i25.0.pwmgen.00.enable TRUE
setp hm2_5i25.0.pwmgen.00.value 0.3
net words hm2_sim.0.bus-words => sampler.0.pin.0
addf hm2_5i25.0.read hm2
addf hm2_5i25.0.write hm2
start
HAL
if ! halcmd -f "$tmp/hm2.hal" > "$tmp/setup.out" 2>&1; then
	echo "setup failed:"; tail -3 "$tmp/setup.out"; exit 0
fi
sleep 0.3
cost=$(thread_cost hm2 "$secs") || { echo "thread_cost failed"; exit 0; }
# thread_cost prints "C cycles, 2 functions, X ns per function call"
echo "$cost" | awk '{ printf "read + write: %.2f us per cycle (%s cycles measured)\n", $5 * 2 / 1000, $1 }'
halcmd addf sampler.0 hm2
halsampler -n 101 | awk 'NR > 1 { d = $1 - prev; if (min == "" || d < min) min = d; if (d > max) max = d }
	{ prev = $1 } END { printf "bus words per cycle: %d..%d (reads and writes, one batched request each)\n", min, max }'
rm -rf "$tmp"
