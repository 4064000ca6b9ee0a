# firmware= with a programmable board (hm2_sim's 5i20, a PLX 9030 card): the
# generated .BIT is found (HAL_FIRMWARE_PATH / firmware_class.path), parsed, its part
# checked, and its bitstream clocked bit-reversed into the simulated configuration
# port, which raises DONE only for the right bit order; the board then registers
# with its usual names. On a flash board (5i25) the keyword is ignored.
. ../../helpers/hm2-bitfile.sh
hm2_bitfile hm2/5i20/hm2test.BIT 2s200pq208
halcmd loadrt hostmot2 || exit 1
halcmd loadrt hm2_sim board=5i20 config="\"firmware=hm2/5i20/hm2test.BIT num_encoders=2\"" || exit 1
echo "5i20 encoders: $(halcmd list pin hm2_5i20.0.encoder | tr ' ' '\n' | grep -c '\.count$')"
halcmd unloadrt hm2_sim
halcmd loadrt hm2_sim board=5i25 config="\"firmware=hm2/5i25/absent.bit\"" || exit 1
echo "5i25 stepgens: $(halcmd list pin hm2_5i25.0.stepgen | tr ' ' '\n' | grep -c '\.position-cmd$')"
halcmd unloadrt hm2_sim
echo "components: $(halcmd list comp)"
halrun -U
