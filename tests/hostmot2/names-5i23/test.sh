# Every HAL name hostmot2 creates for a simulated 5i23 (muxed encoders, 3pwmgen, BSPI
# with a 7i65, UART, LEDs, raw), with type, direction and load-time value; the
# aliases (EMC2's encoder "rawcount"; hostmot2.txt's <module>.<NN>.<pin>.invert_output
# and .is_opendrain for IO pins a module drives); mesa_7i65's names per mesa_7i65(9)
# and mesa_uart's. Encoders 01-07 have the names of 00 (checked by count).
set -e
halcmd loadrt hostmot2
halcmd loadrt hm2_sim board=5i23 'config="enable_raw"'
halcmd loadrt mesa_7i65 bspi_chans=hm2_5i23.0.bspi.0
halcmd loadrt mesa_uart uart_chans=hm2_5i23.0.uart.0
halcmd -s show pin 'hm2_5i23.0.*' | grep -v 'encoder\.0[1-7]\.'
halcmd -s show param 'hm2_5i23.0.*' | grep -v 'encoder\.0[1-7]\.'
echo "encoder pins and params: $(halcmd -s show pin 'hm2_5i23.0.encoder.0*' | wc -l)" \
     "$(halcmd -s show param 'hm2_5i23.0.encoder.0*' | wc -l)"
halcmd list funct
halcmd show alias
halcmd -s show pin 'mesa-*'
halcmd -s show param 'mesa-*'
echo "rawcount: $(halcmd getp hm2_5i23.0.encoder.05.rawcount)"
halcmd setp hm2_5i23.0.3pwmgen.00.pwm-b.invert_output TRUE
echo "gpio.049.invert_output: $(halcmd getp hm2_5i23.0.gpio.049.invert_output)"
halrun -U
