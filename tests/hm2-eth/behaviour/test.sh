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
halcmd loadrt threads name1=thread period1=2000000
halcmd loadrt hostmot2
halcmd loadrt hm2_eth board_ip=127.0.0.1:$ETH_SIM_PORT 'config="enable_raw"'
halcmd setp hm2_5i25.0.packet-read-timeout 100000000
halcmd setp hm2_5i25.0.raw.read_address 0x1100
halcmd setp hm2_5i25.0.watchdog.timeout_ns 300000000
halcmd setp hm2_5i25.0.gpio.017.is_output TRUE
halcmd setp hm2_5i25.0.stepgen.00.position-scale 100
halcmd setp hm2_5i25.0.stepgen.00.maxvel 20
halcmd setp hm2_5i25.0.stepgen.00.maxaccel 200
halcmd setp hm2_5i25.0.stepgen.00.position-cmd 1.5
halcmd setp hm2_5i25.0.stepgen.00.enable TRUE
halcmd addf hm2_5i25.0.read-request thread
halcmd addf hm2_5i25.0.read thread
halcmd addf hm2_5i25.0.write thread
halcmd start
sleep 1.5
show running
echo "position-fb $(halcmd getp hm2_5i25.0.stepgen.00.position-fb)" |
	awk '{ d = $2 - 1.5; if (d < 0) d = -d; print $1, (d <= 0.01 ? "within one step of 1.5" : $2) }'
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
