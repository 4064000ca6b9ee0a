# hm2_eth drives hm2-eth-sim's FPGA model as hm2_sim drives its own: stepgen 00 in
# position mode settles on its command (reads and writes cross the loopback, three
# datagrams per cycle); raw mode reads back the GPIO DDR register; when write stops
# running the watchdog bites (has_bit TRUE, the card says so), clearing has_bit
# restores the pins, and unloading hm2_eth makes the card's watchdog bite at once.
# Generous timeouts (100 ms read timeout, 300 ms watchdog): the test machine may be loaded.
. ../../helpers/hm2-eth-sim.sh
set -e
eth_sim_start --board 5i25
show() {
	echo "$1: has_bit $(halcmd getp hm2_5i25.0.watchdog.has_bit)" \
	     "ddr $(halcmd getp hm2_5i25.0.raw.read_data)" \
	     "io_error $(halcmd getp hm2_5i25.0.io_error)"
}
eth_load 100000000 300000000 enable_raw
halcmd setp hm2_5i25.0.raw.read_address 0x1100
halcmd setp hm2_5i25.0.gpio.017.is_output TRUE
eth_stepgen_cmd 1.5
halcmd start
sleep 1.5
show running
eth_stepgen_settled 1.5
halcmd delf hm2_5i25.0.write thread
sleep 1
show "write stopped"
halcmd addf hm2_5i25.0.write thread
halcmd setp hm2_5i25.0.watchdog.has_bit FALSE
sleep 0.5
show "has_bit cleared"
echo "packet errors: $(halcmd getp hm2_5i25.0.packet-error-total)"
halcmd stop
halcmd unloadrt hm2_eth
sleep 0.3
halrun -U
eth_sim_stop
echo "card says:"
grep -v '^listening\|^datagrams' "$TEST_TMPDIR/eth-sim.log"
