#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# hm2-eth-bench.sh BUILD_DIR [CYCLES]: hm2_eth's round trip per servo cycle
# (read-request -> read -> write: the sum of the three functions' run times, which
# includes waiting for the reply) against hm2-eth-sim on the loopback, 5i25+7i76
# layout with its 5 stepgens moving, 1 ms thread, simulated flavor: median and
# maximum over CYCLES (default 10000) cycles, and datagrams and UDP payload bytes per
# cycle as the simulator counted them. A reply later than 20 ms counts as a packet
# error (reported) instead of stopping the card.
set -u
build=$(cd "${1:-build}" && pwd)
cycles=${2:-10000}
export PATH="$build/bin:$PATH"
export RTAPI_INSTANCE="hm2ethbench-$$"
tmp=$(mktemp -d)
hm2-eth-sim --port-file "$tmp/port" --lifetime 600 >"$tmp/sim.log" 2>&1 &
sim=$!
trap 'halrun -U >/dev/null 2>&1; kill $sim 2>/dev/null; wait $sim 2>/dev/null; rm -rf "$tmp"' EXIT
i=0
while [ ! -s "$tmp/port" ] && [ $i -lt 100 ]; do sleep 0.05; i=$((i + 1)); done
cat > "$tmp/eth.hal" <<HAL
loadrt threads name1=hm2 period1=1000000
loadrt hostmot2
loadrt hm2_eth board_ip=127.0.0.1:$(cat "$tmp/port")
loadrt sampler depth=4000 cfg=sss
setp hm2_5i25.0.watchdog.timeout_ns 1000000000
# measure, do not stop: a loaded machine's late replies count but never set io_error
setp hm2_5i25.0.packet-read-timeout 20000000
setp hm2_5i25.0.packet-error-limit 1000000000
setp hm2_5i25.0.stepgen.00.enable TRUE
setp hm2_5i25.0.stepgen.01.enable TRUE
setp hm2_5i25.0.stepgen.02.enable TRUE
setp hm2_5i25.0.stepgen.03.enable TRUE
setp hm2_5i25.0.stepgen.04.enable TRUE
setp hm2_5i25.0.stepgen.00.control-type TRUE
setp hm2_5i25.0.stepgen.00.velocity-cmd 100
net rq hm2_5i25.0.read-request.time => sampler.0.pin.0
net rd hm2_5i25.0.read.time => sampler.0.pin.1
net wr hm2_5i25.0.write.time => sampler.0.pin.2
addf hm2_5i25.0.read-request hm2
addf hm2_5i25.0.read hm2
addf hm2_5i25.0.write hm2
addf sampler.0 hm2
start
HAL
if ! halcmd -f "$tmp/eth.hal" > "$tmp/setup.out" 2>&1; then
	echo "setup failed:"; tail -3 "$tmp/setup.out"; exit 0
fi
halsampler -n "$cycles" | hm2_eth_rtt
echo "packet errors during the run: $(halcmd getp hm2_5i25.0.packet-error-total)"
halrun -U >/dev/null 2>&1
kill $sim; wait $sim 2>/dev/null
awk '/^datagrams/ {
	gsub(/[(),]/, " ")
	# datagrams received R (IB bytes  Q with reads)  sent S (OB bytes)
	r = $3; ib = $4; q = $6; s = $10; ob = $11
	printf "per cycle: %.2f datagrams to the card (%.0f bytes), %.2f back (%.0f bytes), UDP payload\n",
		r / q, ib / q, s / q, ob / q }' "$tmp/sim.log"
