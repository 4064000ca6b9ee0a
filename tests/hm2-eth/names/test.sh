# hm2_eth against hm2-eth-sim (presenting the 5i25 layout) creates exactly the pins,
# parameters and functions hm2_sim board=5i25 creates, plus the Ethernet ones:
# read-request, the packet-* objects; without read_gpio/write_gpio (not thread-safe).
. ../../helpers/hm2-eth-sim.sh
names() {	# pins, params, functions of hm2_5i25.0 with types and directions
	{ halcmd show pin hm2_5i25.0; halcmd show param hm2_5i25.0; } |
		awk '$NF ~ /^hm2_5i25/ { print $2, $3, $NF }' | grep -v '\.time$\|\.tmax$' | sort
	halcmd show funct hm2_5i25.0 | awk '$NF ~ /^hm2_5i25/ { print "funct FP=" $4, $NF }' 
}
eth_sim_start --board 5i25
halcmd loadrt hostmot2 || exit 1
halcmd loadrt hm2_sim board=5i25 config="\"num_encoders=1 enable_raw\"" || exit 1
names >"$TEST_TMPDIR/sim.names"
halcmd unloadrt hm2_sim
halcmd loadrt hm2_eth board_ip=127.0.0.1:$ETH_SIM_PORT config="\"num_encoders=1 enable_raw\"" || exit 1
names >"$TEST_TMPDIR/eth.names"
echo "hm2_sim: $(wc -l <"$TEST_TMPDIR/sim.names") names, hm2_eth: $(wc -l <"$TEST_TMPDIR/eth.names")"
diff "$TEST_TMPDIR/sim.names" "$TEST_TMPDIR/eth.names" | grep '^[<>]'
halcmd unloadrt hm2_eth
echo "components: $(halcmd list comp)"
halrun -U
eth_sim_stop
