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
# The set-up the behaviour tests share (a simulated 5i25 behind hm2_eth):
#   eth_load READ_TIMEOUT_NS WATCHDOG_NS [CONFIG]  a 2 ms thread, hostmot2, hm2_eth on
#     the simulator with these timeouts, read-request/read/write in the thread (not
#     started yet)
#   eth_stepgen_cmd POS      stepgen 00 in position mode (100 steps per unit) sent to POS
#   eth_stepgen_settled POS  "position-fb within one step of POS", or the value
eth_load() {
	halcmd loadrt threads name1=thread period1=2000000
	halcmd loadrt hostmot2
	halcmd loadrt hm2_eth board_ip=127.0.0.1:$ETH_SIM_PORT ${3:+"config=\"$3\""}
	halcmd setp hm2_5i25.0.packet-read-timeout "$1"
	halcmd setp hm2_5i25.0.watchdog.timeout_ns "$2"
	halcmd addf hm2_5i25.0.read-request thread
	halcmd addf hm2_5i25.0.read thread
	halcmd addf hm2_5i25.0.write thread
}
eth_stepgen_cmd() {
	halcmd setp hm2_5i25.0.stepgen.00.position-scale 100
	halcmd setp hm2_5i25.0.stepgen.00.maxvel 20
	halcmd setp hm2_5i25.0.stepgen.00.maxaccel 200
	halcmd setp hm2_5i25.0.stepgen.00.position-cmd "$1"
	halcmd setp hm2_5i25.0.stepgen.00.enable TRUE
}
eth_stepgen_settled() {
	echo "position-fb $(halcmd getp hm2_5i25.0.stepgen.00.position-fb)" |
		awk -v p="$1" '{ d = $2 - p; if (d < 0) d = -d; print $1, (d <= 0.01 ? "within one step of " p : $2) }'
}
