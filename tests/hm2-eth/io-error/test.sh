# The cable pulled (hm2-eth-sim drops everything after SIGUSR1): every cycle is a
# read timeout, packet-error-level climbs by 2 per cycle to packet-error-limit (10),
# then hm2_eth sets io_error and packet-error-exceeded with one message and hostmot2
# stops touching the card. Plugged in again, nothing changes until the user clears
# io_error: then the level restarts at 0 and the card is driven again. (50 ms read
# timeout: a loaded test machine's delays must not count as errors.)
. ../../helpers/hm2-eth-sim.sh
set -e
eth_sim_start --board 5i25
show() {
	echo "$1: io_error $(halcmd getp hm2_5i25.0.io_error)" \
	     "exceeded $(halcmd getp hm2_5i25.0.packet-error-exceeded)" \
	     "has_bit $(halcmd getp hm2_5i25.0.watchdog.has_bit)"
}
eth_load 50000000 3000000000
halcmd start
sleep 0.3
show running
kill -USR1 "$ETH_SIM_PID"
sleep 1.5
show "cable pulled"
echo "level $(halcmd getp hm2_5i25.0.packet-error-level), errors >= 5: $([ "$(halcmd getp hm2_5i25.0.packet-error-total)" -ge 5 ] && echo yes || echo no)"
kill -USR1 "$ETH_SIM_PID"
sleep 0.3
show "plugged in"
halcmd setp hm2_5i25.0.io_error FALSE
sleep 0.3
show "io_error cleared"
echo "level $(halcmd getp hm2_5i25.0.packet-error-level)"
halrun -U
eth_sim_stop
