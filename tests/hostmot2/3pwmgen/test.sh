# 3pwmgen 00 of a simulated 5i23 (ClockHigh 96 MHz), registers read back in raw mode:
#   value 0x4500: A 0.5 -> 768, B -0.5 -> 257, C 0 -> 512 (10 bits each, 512 = 50 %)
#     = 768 | 257 << 10 | 512 << 20 = 537134848
#   scale 2: A 0.25 -> 640, B -0.25 -> 384 = 537264768
#   rate 0x4800: 20 kHz -> 20000 x 65536 x 2048 / 96e6 = 27962
#   setup 0x4700: dead time 5000 ns -> 102, sample time 0.5 -> 511 << 16 = 33488998
#   enable/fault 0x4600: bit 0 enable, bit 1 fault
# The fault input (IO pin 55) is active low (fault-invert FALSE); pulling it low
# latches fault and clears enable; it stays latched after the input recovers until
# enable is set high again.
set -e
peek() {
	halcmd setp hm2_5i23.0.raw.read_address "$1"
	sleep 0.05
	echo "$2: $(halcmd getp hm2_5i23.0.raw.read_data)"
}
halcmd loadrt threads name1=thread period1=1000000
halcmd loadrt hostmot2
halcmd loadrt hm2_sim board=5i23 config=enable_raw
halcmd setp hm2_5i23.0.watchdog.timeout_ns 1000000000
halcmd setp hm2_sim.0.io.055.in TRUE
halcmd setp hm2_5i23.0.3pwmgen.00.A-value 0.5
halcmd setp hm2_5i23.0.3pwmgen.00.B-value -0.5
halcmd setp hm2_5i23.0.3pwmgen.00.enable TRUE
halcmd addf hm2_5i23.0.read thread
halcmd addf hm2_5i23.0.write thread
halcmd start
peek 0x4500 "value"
peek 0x4800 "rate"
peek 0x4700 "setup"
peek 0x4600 "enable/fault"
echo "fault pin: $(halcmd getp hm2_5i23.0.3pwmgen.00.fault)"
halcmd setp hm2_5i23.0.3pwmgen.00.scale 2
peek 0x4500 "value at scale 2"
halcmd setp hm2_sim.0.io.055.in FALSE
peek 0x4600 "fault input low"
halcmd setp hm2_sim.0.io.055.in TRUE
peek 0x4600 "input back high"
echo "fault pin: $(halcmd getp hm2_5i23.0.3pwmgen.00.fault)"
halcmd setp hm2_5i23.0.3pwmgen.00.enable FALSE
sleep 0.05
halcmd setp hm2_5i23.0.3pwmgen.00.enable TRUE
peek 0x4600 "enable set high again"
echo "fault pin: $(halcmd getp hm2_5i23.0.3pwmgen.00.fault)"
halrun -U
