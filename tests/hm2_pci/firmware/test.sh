# firmware= through each PLX bridge model: a generated .BIT is found, its part
# checked against the card (5i22, 4i69 and 3x20 sizes come from the subsystem ID),
# and its bitstream sent bit-reversed to the configuration data port (9030: /WRITE
# low, /INIT and DONE from the GPIO register; 9054/9056: DONE from CNTRL); the model
# raises DONE only for the right bit order, then the card registers with its names
# (every PCI card: 5i20 and 4i65 on a 9030, 5i23, 4i68, 4i69, 5i22, 5i21 on a 9054,
# 3x20 on a 9056, 5i24, 5i25, 6i25 without a bridge).
# A flash card (5i25, 6i25) ignores firmware=.
. ../../helpers/hm2-bitfile.sh
hm2_bitfile hm2/5i20/t.bit 2s200pq208
hm2_bitfile hm2/5i23/t.bit 3s400pq208
hm2_bitfile hm2/4i69/t.bit 6slx16ftg256
hm2_bitfile hm2/5i22/t.bit 3s1000fg320
hm2_bitfile hm2/5i21/t.bit 3s400pq208
hm2_bitfile hm2/3x20/t.bit 3s1000fg456
halcmd loadrt hostmot2 || exit 1
card() {	# card BOARD FIRMWARE: load, count the encoders and LEDs, unload
	halcmd loadrt hm2_sim bus=pci board=$1 || exit 1
	halcmd loadrt hm2_pci "config=\"firmware=$2\"" || exit 1
	echo "$1: $(halcmd list comp)/ encoders $(halcmd list pin "hm2_$1.0.encoder" | tr ' ' '\n' | grep -c '\.count$')" \
	     "leds $(halcmd list pin "hm2_$1.0.led" | tr ' ' '\n' | grep -c CR)"
	halcmd unloadrt hm2_pci
	halcmd unloadrt hm2_sim
}
card 5i20 hm2/5i20/t.bit
card 4i65 hm2/5i20/t.bit
card 5i23 hm2/5i23/t.bit
card 4i68 hm2/5i23/t.bit
card 4i69 hm2/4i69/t.bit
card 5i22 hm2/5i22/t.bit
card 5i21 hm2/5i21/t.bit
card 3x20 hm2/3x20/t.bit
card 5i24 hm2/5i24/none.bit
card 5i25 hm2/5i25/none.bit
card 6i25 hm2/6i25/none.bit
# two cards: config entries in probe order, names counted per type
halcmd loadrt hm2_sim bus=pci board=5i20,5i25,5i20 || exit 1
halcmd loadrt hm2_pci 'config="firmware=hm2/5i20/t.bit num_encoders=1,num_stepgens=2,num_encoders=3"' || exit 1
for b in hm2_5i20.0 hm2_5i25.0 hm2_5i20.1; do
	echo "$b: encoders $(halcmd list pin "$b.encoder" | tr ' ' '\n' | grep -c '\.count$')" \
	     "stepgens $(halcmd list pin "$b.stepgen" | tr ' ' '\n' | grep -c '\.position-cmd$')"
done
halcmd unloadrt hm2_pci
halcmd unloadrt hm2_sim
echo "components: $(halcmd list comp)"
halrun -U
