# Every hm2_7i43 refusal prints its message and leaves nothing of the driver loaded
# (only hostmot2 and the simulated ports stay, and the port can be claimed again):
# no firmware=, a missing file, a bitfile for the other FPGA size, a truncated file,
# a bitstream the FPGA does not accept (stored bit-reversed: DONE never rises, so no
# HostMot2 cookie answers, with 32-bit and then byte transfers), and a port with no
# board on it (every EPP cycle times out during the reset); no port (ioaddr=-1) and a
# config= entry without its ioaddr= entry.
. ../../helpers/hm2-bitfile.sh
load() {
	halcmd loadrt hm2_7i43 "$@" >"$TEST_TMPDIR/msg" 2>&1
	rc=$?
	sed 's/(comp [0-9]*)/(comp N)/g' "$TEST_TMPDIR/msg"
	echo "exit $rc; components: $(halcmd list comp)"
}
hm2_bitfile hm2/7i43/good.BIT 3s400tq144
hm2_bitfile hm2/7i43/small.BIT 3s200tq144
hm2_bitfile hm2/7i43/short.BIT 3s400tq144 short
hm2_bitfile hm2/7i43/reversed.BIT 3s400tq144 reversed
halcmd loadrt hostmot2 || exit 1
halcmd loadrt sim_parport io=0x2000,0x3000 board=7i43,none || exit 1
load ioaddr=0x2000 config="\"num_encoders=1\""
load ioaddr=0x2000 config="\"firmware=hm2/7i43/missing.BIT\""
load ioaddr=0x2000 config="\"firmware=hm2/7i43/small.BIT\""
load ioaddr=0x2000 config="\"firmware=hm2/7i43/short.BIT\""
load ioaddr=0x2000 config="\"firmware=hm2/7i43/reversed.BIT\""
load ioaddr=0x3000 config="\"firmware=hm2/7i43/good.BIT\""
load ioaddr=-1
load ioaddr=0x2000 config=a,b
load ioaddr=0x2000 config="\"firmware=hm2/7i43/good.BIT\""
halcmd unloadrt hm2_7i43
halrun -U
