# Packet loss injected by hm2-eth-sim: every 10th read request and every 7th write
# datagram lost. A lost request is a read timeout (the cycle's read is skipped), a
# lost write shows as the card's echoed write sequence lagging: both are counted in
# packet-error-total, the level rises by 2 and decays by 1 per good cycle, so it
# never reaches the limit: io_error stays FALSE. (While a lost request stalls the
# thread for the read timeout the stepgen runs on at its last rate and its position
# loop overshoots; once the losses end it settles on its command.)
# 2 ms thread, 50 ms read timeout: only injected losses (not a loaded machine's
# scheduling delays) should time out.
. ../../helpers/hm2-eth-sim.sh
set -e
eth_sim_start --board 5i25 --drop-reads 10 --drop-writes 7 --loss-paused
eth_load 50000000 300000000
eth_stepgen_cmd 1.5
halcmd start
sleep 0.2
kill -USR2 "$ETH_SIM_PID"	# losses from now on (registration is not retried)
sleep 2
total=$(halcmd getp hm2_5i25.0.packet-error-total)
echo "packet errors counted: $([ "$total" -ge 5 ] && echo "yes (at least 5)" || echo "only $total")"
echo "io_error $(halcmd getp hm2_5i25.0.io_error) exceeded $(halcmd getp hm2_5i25.0.packet-error-exceeded)" \
     "level below limit: $([ "$(halcmd getp hm2_5i25.0.packet-error-level)" -lt 10 ] && echo yes || echo no)"
kill -USR2 "$ETH_SIM_PID"	# losses end: the stepgen settles (recovered)
sleep 1
eth_stepgen_settled 1.5
halrun -U
eth_sim_stop
