# hm2_7i43 on a simulated parallel port with a 7i43 on its cable (sim_parport
# board=7i43, firmware programmed through the CPLD model) creates exactly the pins,
# parameters and functions hm2_sim board=7i43 creates for the same SVST4_4 layout,
# without read_gpio/write_gpio (the EPP bus is not thread-safe).
. ../../helpers/hm2-bitfile.sh
names() {	# pins, params, functions of hm2_7i43.0 with types and directions
	{ halcmd show pin hm2_7i43.0; halcmd show param hm2_7i43.0; } |
		awk '$NF ~ /^hm2_7i43/ { print $2, $3, $NF }' | grep -v '\.time$\|\.tmax$' | sort
	halcmd show funct hm2_7i43.0 | awk '$NF ~ /^hm2_7i43/ { print "funct FP=" $4, $NF }'
}
hm2_bitfile hm2/7i43/SVST4_4.BIT 3s400tq144
halcmd loadrt hostmot2 || exit 1
halcmd loadrt hm2_sim board=7i43 config="\"num_encoders=2 num_stepgens=3 enable_raw\"" || exit 1
names >"$TEST_TMPDIR/sim.names"
halcmd unloadrt hm2_sim
halcmd loadrt sim_parport io=0x2000 board=7i43 || exit 1
halcmd loadrt hm2_7i43 ioaddr=0x2000 \
	config="\"firmware=hm2/7i43/SVST4_4.BIT num_encoders=2 num_stepgens=3 enable_raw\"" || exit 1
names >"$TEST_TMPDIR/epp.names"
echo "hm2_sim: $(wc -l <"$TEST_TMPDIR/sim.names") names, hm2_7i43: $(wc -l <"$TEST_TMPDIR/epp.names")"
# (unified: busybox diff has no other format) only hm2_sim's, only hm2_7i43's
diff -u "$TEST_TMPDIR/sim.names" "$TEST_TMPDIR/epp.names" | grep '^[-+][^-+]'
echo "gpio pins with .in: $(halcmd list pin hm2_7i43.0.gpio | tr ' ' '\n' | grep -c '\.in$')," \
	"leds: $(halcmd list pin hm2_7i43.0.led | tr ' ' '\n' | grep -c .)"
halcmd unloadrt hm2_7i43
echo "components: $(halcmd list comp)"
halrun -U
