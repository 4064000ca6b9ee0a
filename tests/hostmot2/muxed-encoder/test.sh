# Eight muxed encoders on a simulated 5i23: encoders 02 and 03 share IO pins 27-29
# through an outside multiplexer switched by the select output on IO pin 36 (hm2_sim
# models the multiplexer: hm2_sim.0.mux.NN.a/b/index are the encoders behind it).
# The select line is driven from load on (port 1 DDR = bit 12, before any write);
# encoder 03 counts 8 quadrature steps up while 02, on the same pins, counts 3 down.
# muxed-skew 100 ns at 48 MHz = 5 clocks, muxed-sample-frequency 8 MHz -> 4:
# the filter register 0x3900 = 5 << 28 | 4 = 1342177284.
set -e
peek() {
	halcmd setp hm2_5i23.0.raw.read_address "$1"
	sleep 0.05
	echo "$2: $(halcmd getp hm2_5i23.0.raw.read_data)"
}
step() {	# encoder A B
	halcmd setp hm2_sim.0.mux.$1.a "$2"
	halcmd setp hm2_sim.0.mux.$1.b "$3"
	sleep 0.02
}
halcmd loadrt threads name1=thread period1=1000000
halcmd loadrt hostmot2
halcmd loadrt hm2_sim board=5i23 config=enable_raw
halcmd setp hm2_5i23.0.watchdog.timeout_ns 1000000000
halcmd addf hm2_5i23.0.read thread
halcmd start
peek 0x1104 "P3 DDR before the first write"
halcmd addf hm2_5i23.0.write thread
for i in 1 2; do
	step 03 1 0; step 03 1 1; step 03 0 1; step 03 0 0
done
step 02 0 1; step 02 1 1; step 02 1 0
sleep 0.05
echo "counts: 02 $(halcmd getp hm2_5i23.0.encoder.02.count) 03 $(halcmd getp hm2_5i23.0.encoder.03.count)" \
     "others $(halcmd getp hm2_5i23.0.encoder.00.count) $(halcmd getp hm2_5i23.0.encoder.01.count)" \
     "$(halcmd getp hm2_5i23.0.encoder.04.count)"
echo "inputs 03: $(halcmd getp hm2_5i23.0.encoder.03.input-a) $(halcmd getp hm2_5i23.0.encoder.03.input-b)"
halcmd setp hm2_5i23.0.encoder.muxed-skew 100
peek 0x3900 "filter rate and skew"
halrun -U
