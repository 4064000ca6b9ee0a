# Programming through the 7i43's CPLD: hm2_7i43 resets the board, reads the FPGA's
# size from the CPLD (400K on port 0, 200K on port 1), and clocks the bitstream of
# the bitfile for that part into the CPLD's data register bit-reversed; the model's
# configuration port counts the bytes (all 216 of the generated file) and raises
# DONE only for the Xilinx sync word in the card's bit order. Then HostMot2 answers
# over EPP: the IDROM gives the board's size. Byte transfers on port 1 (epp_wide=0).
. ../../helpers/hm2-bitfile.sh
hm2_bitfile hm2/7i43/big.BIT 3s400tq144
hm2_bitfile hm2/7i43/small.BIT 3s200tq144
halcmd loadrt hostmot2 || exit 1
halcmd loadrt sim_parport io=0x2000,0x3000 board=7i43,7i43_200 || exit 1
echo "before: done $(halcmd getp sim-parport.0.7i43.done) $(halcmd getp sim-parport.1.7i43.done)"
halcmd loadrt hm2_7i43 ioaddr=0x2000,0x3000 epp_wide=1,0 \
	config="\"firmware=hm2/7i43/big.BIT,firmware=hm2/7i43/small.BIT num_stepgens=1\"" || exit 1
for n in 0 1; do
	echo "board $n: done $(halcmd getp sim-parport.$n.7i43.done)" \
		"config-bytes $(halcmd getp sim-parport.$n.7i43.config-bytes)" \
		"ecr $(halcmd getp sim-parport.$n.ecr) control $(halcmd getp sim-parport.$n.control)" \
		"stepgens $(halcmd list pin hm2_7i43.$n.stepgen | tr ' ' '\n' | grep -c '\.position-cmd$')"
done
halcmd unloadrt hm2_7i43
echo "components: $(halcmd list comp)"
halrun -U
