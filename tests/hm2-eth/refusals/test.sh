# Every hm2_eth load refusal prints its message and leaves nothing loaded (only
# hostmot2 stays): nothing listening (UDP timeout), a reply of the wrong length
# (wrong LBP16 reply), a card without a HostMot2 cookie, an IDROM the core refuses,
# a config-string error, bad or missing board_ip, a config entry without a board.
. ../../helpers/hm2-eth-sim.sh
load() {
	halcmd loadrt hm2_eth "$@" >"$TEST_TMPDIR/msg" 2>&1
	rc=$?
	sed "s/(comp [0-9]*)/(comp N)/g; s/127\.0\.0\.1:$ETH_SIM_PORT/127.0.0.1:PORT/g" "$TEST_TMPDIR/msg"
	echo "exit $rc"
}
halcmd loadrt hostmot2 || exit 1
# a port nobody listens on (the simulator's, after it ended): ICMP port unreachable
eth_sim_start
eth_sim_stop
load board_ip=127.0.0.1:$ETH_SIM_PORT
# a card that never answers (every request lost)
eth_sim_start --drop-reads 1
load board_ip=127.0.0.1:$ETH_SIM_PORT
eth_sim_stop
eth_sim_start --bad-reply
load board_ip=127.0.0.1:$ETH_SIM_PORT
eth_sim_stop
eth_sim_start --fault no-cookie
load board_ip=127.0.0.1:$ETH_SIM_PORT
eth_sim_stop
eth_sim_start --fault port-width
load board_ip=127.0.0.1:$ETH_SIM_PORT
eth_sim_stop
eth_sim_start
load board_ip=127.0.0.1:$ETH_SIM_PORT 'config="num_encoders=2"'
load board_ip=127.0.0.1:$ETH_SIM_PORT 'config="firmware=hm2/7i92/x.bit bogus"'
eth_sim_stop
load board_ip=192.168.1
load board_ip=127.0.0.1:0
load board_ip=127.0.0.1:99999
load
load board_ip=127.0.0.1:1 config=a,b
echo "components: $(halcmd list comp)"
halrun -U
