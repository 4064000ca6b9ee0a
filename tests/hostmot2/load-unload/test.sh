# 100 load/unload cycles of hostmot2 with three simulated boards (one of each layout)
# and the BSPI/UART sub-drivers mesa_7i65 and mesa_uart leave nothing behind: the
# same components and the same HAL memory use as before. mesa_7i65 is unloaded after
# its board (its channel is gone by then), mesa_uart before.
set -e
. ../../helpers/hal-cycles.sh
halcmd loadrt threads name1=thread period1=1000000
# 100 cycles; 25 in the kernel flavor, where the test VM (qemu without KVM) needs
# about a second per insmod/rmmod cycle and the runner allows 120 s a test
cycles=100
[ "${HAL_TEST_FLAVOR:-sim}" != kernel ] || cycles=25
hal_cycles $cycles <<'CYCLE'
loadrt hostmot2
loadrt hm2_sim board=5i25,5i20,5i23 config="enable_raw,num_encoders=4,num_encoders=2"
loadrt mesa_7i65 bspi_chans=hm2_5i23.0.bspi.0
loadrt mesa_uart uart_chans=hm2_5i23.0.uart.0
addf hm2_5i25.0.read thread
addf hm2_5i20.0.write thread
addf hm2_5i23.0.write thread
addf mesa-uart.0.send thread
unloadrt mesa_uart
unloadrt hm2_sim
unloadrt mesa_7i65
unloadrt hostmot2
CYCLE
halrun -U
