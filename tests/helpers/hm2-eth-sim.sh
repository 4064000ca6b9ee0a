# hm2-eth-sim.sh - sourced by the hm2_eth tests: runs hm2-eth-sim (an LBP16 card on
# 127.0.0.1 in front of hm2_sim's FPGA model) in the background for one test.
#   eth_sim_start [ARGS...]  starts it on a free port; sets ETH_SIM_PORT, ETH_SIM_PID,
#                            its output goes to $TEST_TMPDIR/eth-sim.log
#   eth_sim_stop             ends it (SIGTERM) and waits for it
# The simulator also ends by itself after 120 s, so a test that dies leaves nothing.
ETH_SIM_PID=
eth_sim_start() {
	rm -f "$TEST_TMPDIR/eth-sim.port"
	hm2-eth-sim --port-file "$TEST_TMPDIR/eth-sim.port" --lifetime 120 "$@" \
		>"$TEST_TMPDIR/eth-sim.log" 2>&1 &
	ETH_SIM_PID=$!
	i=0
	while [ ! -s "$TEST_TMPDIR/eth-sim.port" ] && [ $i -lt 100 ]; do
		sleep 0.05
		i=$((i + 1))
	done
	ETH_SIM_PORT=$(cat "$TEST_TMPDIR/eth-sim.port" 2>/dev/null)
	[ -n "$ETH_SIM_PORT" ] || { echo "hm2-eth-sim did not start"; cat "$TEST_TMPDIR/eth-sim.log"; exit 1; }
}
eth_sim_stop() {
	[ -n "$ETH_SIM_PID" ] || return 0
	kill "$ETH_SIM_PID" 2>/dev/null
	wait "$ETH_SIM_PID" 2>/dev/null
	ETH_SIM_PID=
}
