# The hm2 watchdog (5 ms default) sleeps until the first write(), then write() pets
# it. When write stops running the watchdog bites: has_bit goes TRUE and every IO
# pin is released (GPIO 017, driven high, falls to the outside level, 0; stepgen
# 00's step pin stops being driven). Clearing has_bit with write running again
# restores the pins. Timing: the timeout is 1 s, and each phase that checks it
# lasts twice that. Between two cycles of the 1 ms thread a machine can stall: the
# simulated flavor's thread may not be realtime, and in the kernel-test VM (qemu
# TCG on a loaded host) gaps of 64-74 ms were measured, with write itself once
# taking over 20 ms, so a 100 ms timeout bit there now and then while write ran.
set -e
show() {
	echo "$1: has_bit $(halcmd getp hm2_5i25.0.watchdog.has_bit)" \
	     "gpio017 $(halcmd getp hm2_sim.0.io.017.out)" \
	     "ddr $(halcmd getp hm2_5i25.0.raw.read_data)"
}
halcmd loadrt threads name1=thread period1=1000000
halcmd loadrt hostmot2
halcmd loadrt hm2_sim board=5i25 'config="enable_raw"'
halcmd setp hm2_5i25.0.raw.read_address 0x1100
halcmd setp hm2_5i25.0.watchdog.timeout_ns 1000000000
halcmd setp hm2_5i25.0.gpio.017.is_output TRUE
halcmd setp hm2_5i25.0.gpio.017.out TRUE
halcmd addf hm2_5i25.0.read thread
halcmd addf hm2_5i25.0.write thread
show loaded
halcmd start
sleep 2
show running
halcmd delf hm2_5i25.0.write thread
sleep 2
show "write stopped"
halcmd addf hm2_5i25.0.write thread
sleep 0.5
show "write back, has_bit still set"
halcmd setp hm2_5i25.0.watchdog.has_bit FALSE
sleep 0.5
show "has_bit cleared"
halrun -U
