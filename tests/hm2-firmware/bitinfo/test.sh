# hm2-bitinfo prints a .BIT file's header and the boards it fits; --board checks one
# board; a broken file or a board it does not fit exits 1 with the reason.
. ../../helpers/hm2-bitfile.sh
hm2_bitfile hm2/7i43/SV8.BIT 3s400tq144
hm2_bitfile hm2/x/odd.bit xc7a35t
hm2_bitfile hm2/5i20/short.bit 2s200pq208 short
cd "$HM2_FW_DIR" || exit 1
run() { hm2-bitinfo "$@" 2>&1; echo "exit $?"; }
run hm2/7i43/SV8.BIT
run --board 7i43 hm2/7i43/SV8.BIT
run --board 5i20 hm2/7i43/SV8.BIT
run --board 5i25 hm2/7i43/SV8.BIT
run --board 9x99 hm2/7i43/SV8.BIT
run hm2/x/odd.bit hm2/5i20/short.bit
run hm2/none.bit
run --board
