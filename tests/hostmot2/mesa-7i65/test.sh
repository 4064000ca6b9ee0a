# mesa_7i65 on BSPI 0 of a simulated 5i23 (hm2_sim's 7i65 model: AD5754 DACs on CS1/CS2,
# an AD7329 ADC on CS3 that measures the DAC outputs, a CPLD on CS4). Every cycle
# hostmot2's write sends the DAC, ADC and CPLD frames mesa_7i65 filled; read hands it
# the replies. DAC code = out x scale x 3276.7 (+-10 V); analogue.M.in = ADC code /
# 409.6 with ADC code = DAC code / 8: out 0.5 x 10 -> 16383 -> 4.99756 V. Channel 2 is
# unipolar (negative -> 0), channel 3 has scale 7. When write stops no frames go out (the inputs keep their last values) and the 7i65's own
# watchdog (50 ms) bites: DACs to 0, enables off; write back, all restored.
set -e
show() {
	echo "$1: dac0 $(halcmd getp hm2_sim.0.7i65.dac-0) dac1 $(halcmd getp hm2_sim.0.7i65.dac-1)" \
	     "dac2 $(halcmd getp hm2_sim.0.7i65.dac-2) dac3 $(halcmd getp hm2_sim.0.7i65.dac-3)" \
	     "in0 $(halcmd getp mesa-7i65.0.analogue.0.in) in1 $(halcmd getp mesa-7i65.0.analogue.1.in)" \
	     "in2 $(halcmd getp mesa-7i65.0.analogue.2.in) in3 $(halcmd getp mesa-7i65.0.analogue.3.in)" \
	     "enable1 $(halcmd getp hm2_sim.0.7i65.enable-1) digital2 $(halcmd getp mesa-7i65.0.digital.2.in)" \
	     "bitten $(halcmd getp hm2_sim.0.7i65.watchdog-bitten)"
}
halcmd loadrt threads name1=thread period1=1000000
halcmd loadrt hostmot2
halcmd loadrt hm2_sim board=5i23
halcmd loadrt mesa_7i65 bspi_chans=hm2_5i23.0.bspi.0
halcmd setp hm2_5i23.0.watchdog.timeout_ns 1000000000
halcmd setp mesa-7i65.0.analogue.0.out 0.5
halcmd setp mesa-7i65.0.analogue.1.out -0.25
halcmd setp mesa-7i65.0.is-bipolar-2 FALSE
halcmd setp mesa-7i65.0.analogue.2.out -0.5
halcmd setp mesa-7i65.0.scale-3 7
halcmd setp mesa-7i65.0.analogue.3.out 1.5
halcmd setp mesa-7i65.0.enable.1.out TRUE
halcmd setp hm2_sim.0.7i65.digital-in-2 TRUE
halcmd addf hm2_5i23.0.read thread
halcmd addf hm2_5i23.0.write thread
show loaded
halcmd start
sleep 0.3
show running
halcmd delf hm2_5i23.0.write thread
sleep 0.3
show "write stopped"
halcmd addf hm2_5i23.0.write thread
sleep 0.3
show "write back"
halrun -U
