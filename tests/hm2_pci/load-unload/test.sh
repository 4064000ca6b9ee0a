# 25 load/unload cycles of hm2_pci over three simulated cards (a 5i25, a 5i20 behind
# a PLX 9030 programmed with firmware= each time, a 5i23 behind a 9054), with their
# functions in a thread, leave nothing behind: the same components, functions and
# HAL memory use as before.
set -e
. ../../helpers/hm2-bitfile.sh
. ../../helpers/hal-cycles.sh
hm2_bitfile hm2/5i20/t.bit 2s200pq208
halcmd loadrt threads name1=thread period1=1000000
halcmd loadrt hostmot2
halcmd loadrt hm2_sim bus=pci board=5i25,5i20,5i23
hal_cycles 25 <<'CYCLE'
loadrt hm2_pci config="enable_raw,firmware=hm2/5i20/t.bit num_encoders=4,num_encoders=2"
addf hm2_5i25.0.read thread
addf hm2_5i20.0.write thread
addf hm2_5i23.0.read thread
unloadrt hm2_pci
CYCLE
halcmd unloadrt hm2_sim
halcmd unloadrt hostmot2
echo "components: $(halcmd list comp)"
halrun -U
