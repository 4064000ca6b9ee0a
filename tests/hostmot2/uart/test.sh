# UART 0 of a simulated 5i23 has a loop-back plug (hm2_sim): mesa_uart queues
# tx-bytes bytes of tx-data-NN when tx-send is set (and clears it); the receive
# function takes what arrived. 115200 bit/s: three bytes take 0.26 ms. Then the RX
# bit rate is changed behind the driver's back (raw write to the RX rate register
# 0x6600): the bytes are lost, rx-count stays.
set -e
. ../../helpers/wait-getp.sh
show() {
	echo "$1: tx-send $(halcmd getp mesa-uart.0.tx-send) rx-count $(halcmd getp mesa-uart.0.rx-count)" \
	     "rx $(halcmd getp mesa-uart.0.rx-data-00) $(halcmd getp mesa-uart.0.rx-data-01)" \
	     "$(halcmd getp mesa-uart.0.rx-data-02) $(halcmd getp mesa-uart.0.rx-data-03)"
}
halcmd loadrt threads name1=thread period1=1000000
halcmd loadrt hostmot2
halcmd loadrt hm2_sim board=5i23 config=enable_raw
halcmd loadrt mesa_uart uart_chans=hm2_5i23.0.uart.0
halcmd setp hm2_5i23.0.watchdog.timeout_ns 1000000000
halcmd addf hm2_5i23.0.read thread
halcmd addf mesa-uart.0.receive thread
halcmd addf mesa-uart.0.send thread
halcmd addf hm2_5i23.0.write thread
halcmd start
halcmd setp mesa-uart.0.tx-data-00 0x48
halcmd setp mesa-uart.0.tx-data-01 0x4d
halcmd setp mesa-uart.0.tx-data-02 0x32
halcmd setp mesa-uart.0.tx-bytes 3
halcmd setp mesa-uart.0.tx-send TRUE
wait_getp mesa-uart.0.rx-count 3
show "3 bytes"
halcmd setp mesa-uart.0.tx-data-00 0xff
halcmd setp mesa-uart.0.tx-data-01 0x00
halcmd setp mesa-uart.0.tx-data-02 0x7e
halcmd setp mesa-uart.0.tx-data-03 0x81
halcmd setp mesa-uart.0.tx-bytes 4
halcmd setp mesa-uart.0.tx-send TRUE
wait_getp mesa-uart.0.rx-count 7
show "4 more"
halcmd setp hm2_5i23.0.raw.write_address 0x6600
halcmd setp hm2_5i23.0.raw.write_data 1000
halcmd setp hm2_5i23.0.raw.write_strobe TRUE
sleep 0.1
halcmd setp mesa-uart.0.tx-send TRUE
sleep 0.3
show "rx rate differs"
halrun -U
