# Every firmware= refusal prints one message naming the board, the file and the
# reason, and leaves nothing loaded (only hostmot2 stays): a missing file, a wrong
# part, a truncated file, a file that is not a .BIT, a bitstream the configuration
# port does not accept (stored bit-reversed: wrong bit order, DONE never rises).
. ../../helpers/hm2-bitfile.sh
load() {
	halcmd loadrt hm2_sim board=5i20 "config=\"firmware=$1\"" >"$TEST_TMPDIR/msg" 2>&1
	rc=$?
	sed 's/(comp [0-9]*)/(comp N)/g' "$TEST_TMPDIR/msg"
	echo "exit $rc"
}
hm2_bitfile hm2/5i20/wrongpart.bit 3s400pq208
hm2_bitfile hm2/5i20/short.bit 2s200pq208 short
hm2_bitfile hm2/5i20/header.bit 2s200pq208 badheader
hm2_bitfile hm2/5i20/reversed.bit 2s200pq208 reversed
halcmd loadrt hostmot2 || exit 1
load hm2/5i20/missing.bit
load hm2/5i20/wrongpart.bit
load hm2/5i20/short.bit
load hm2/5i20/header.bit
load hm2/5i20/reversed.bit
load ../secret.bit
echo "components: $(halcmd list comp)"
halrun -U
