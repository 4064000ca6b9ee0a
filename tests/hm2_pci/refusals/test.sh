# Every refusal of hm2_pci prints its message and leaves nothing loaded (only
# hostmot2 and the simulated cards stay): firmware missing, for the wrong part, cut
# short, not a .BIT, stored bit-reversed (the configuration port never sees the
# sync word: DONE stays low); a PLX bridge whose DONE never rises (9030 and 9054),
# whose DONE is stuck high (no reset), whose /INIT never rises; a bad IDROM cookie
# behind the bridge; no card at all; a config entry for a card that is not there.
. ../../helpers/hm2-bitfile.sh
hm2_bitfile hm2/5i20/t.bit 2s200pq208
hm2_bitfile hm2/5i23/t.bit 3s400pq208
hm2_bitfile hm2/5i20/wrongpart.bit 3s400pq208
hm2_bitfile hm2/5i20/short.bit 2s200pq208 short
hm2_bitfile hm2/5i20/header.bit 2s200pq208 badheader
hm2_bitfile hm2/5i20/reversed.bit 2s200pq208 reversed
hm2_bitfile hm2/5i23/reversed.bit 3s400pq208 reversed
show() {	# the message, the exit status, what is loaded
	sed 's/(comp [0-9]*)/(comp N)/g' "$TEST_TMPDIR/msg"
	echo "exit $1; loaded: $(halcmd list comp)"
}
pci() {		# pci BOARD FAULT CONFIG
	halcmd loadrt hm2_sim bus=pci board=$1 ${2:+fault=$2} || exit 1
	halcmd loadrt hm2_pci "config=\"$3\"" >"$TEST_TMPDIR/msg" 2>&1
	show $?
	halcmd unloadrt hm2_pci 2>/dev/null
	halcmd unloadrt hm2_sim
}
halcmd loadrt hostmot2 || exit 1
pci 5i20 "" firmware=hm2/5i20/missing.bit
pci 5i20 "" firmware=hm2/5i20/wrongpart.bit
pci 5i20 "" firmware=hm2/5i20/short.bit
pci 5i20 "" firmware=hm2/5i20/header.bit
pci 5i20 "" firmware=hm2/5i20/reversed.bit
pci 5i23 "" firmware=hm2/5i23/reversed.bit
pci 5i20 no-done firmware=hm2/5i20/t.bit
pci 4i68 no-done firmware=hm2/5i23/t.bit
pci 5i20 done-stuck firmware=hm2/5i20/t.bit
pci 5i23 done-stuck firmware=hm2/5i23/t.bit
pci 4i65 init-stuck firmware=hm2/5i20/t.bit
pci 5i20 no-cookie firmware=hm2/5i20/t.bit
pci 6i25 no-cookie ""
# no card; a config entry beyond the cards found
halcmd loadrt hm2_pci >"$TEST_TMPDIR/msg" 2>&1
show $?
halcmd loadrt hm2_sim bus=pci board=5i25 || exit 1
halcmd loadrt hm2_pci 'config="num_encoders=1,num_encoders=2"' >"$TEST_TMPDIR/msg" 2>&1
show $?
halcmd unloadrt hm2_sim
# hm2_sim's own refusals in bus=pci
halcmd loadrt hm2_sim bus=pci board=9x99 >"$TEST_TMPDIR/msg" 2>&1; show $?
halcmd loadrt hm2_sim bus=pci board=5i25 fault=no-done >"$TEST_TMPDIR/msg" 2>&1; show $?
halcmd loadrt hm2_sim bus=pci board=5i25 config=enable_raw >"$TEST_TMPDIR/msg" 2>&1; show $?
halcmd loadrt hm2_sim bus=isa board=5i25 >"$TEST_TMPDIR/msg" 2>&1; show $?
halrun -U
