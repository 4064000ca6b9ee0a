# Raw mode: read_data follows read_address every read() (the IO cookie at 0x100,
# pwmgen's PWM DDS at 0x4200 and mode at 0x4100 as pwm_frequency and output-type
# change); a write_strobe writes write_data to write_address once and clears itself.
set -e
peek() {
	halcmd setp hm2_5i25.0.raw.read_address "$1"
	sleep 0.1
	echo "$2: $(halcmd getp hm2_5i25.0.raw.read_data)"
}
halcmd loadrt threads name1=thread period1=1000000
halcmd loadrt hostmot2
halcmd loadrt hm2_sim board=5i25 'config="enable_raw"'
halcmd setp hm2_5i25.0.watchdog.timeout_ns 1000000000
halcmd addf hm2_5i25.0.read thread
halcmd addf hm2_5i25.0.write thread
halcmd start
peek 0x100 "cookie"
peek 0x4200 "pwm dds at 20 kHz (12 bits)"
peek 0x4100 "pwm mode: 12 bits, double buffered"
halcmd setp hm2_5i25.0.pwmgen.pwm_frequency 100000
peek 0x4200 "pwm dds at 100 kHz (10 bits)"
peek 0x4100 "pwm mode: 10 bits"
halcmd setp hm2_5i25.0.pwmgen.00.output-type 3
peek 0x4100 "pdm mode"
halcmd setp hm2_5i25.0.pwmgen.pwm_frequency 10000000
sleep 0.1
echo "pwm_frequency clipped to $(halcmd getp hm2_5i25.0.pwmgen.pwm_frequency)"
halcmd setp hm2_5i25.0.raw.write_address 0x6000
halcmd setp hm2_5i25.0.raw.write_data 1234
halcmd setp hm2_5i25.0.raw.write_strobe TRUE
peek 0x6000 "written"
echo "strobe after: $(halcmd getp hm2_5i25.0.raw.write_strobe)"
halrun -U
