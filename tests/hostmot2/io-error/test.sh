# Transport failure and recovery: with hm2_sim's bus-error set every transfer fails;
# hostmot2 sets io_error, says so once, and stops touching the board (a GPIO change
# does not reach it). Repairing the bus is not enough: the user clears io_error,
# and the next write() rewrites every register and resumes. (A 4 s watchdog
# timeout: the pause must not make it bite, which would release the pin too.)
set -e
show() { echo "$1: io_error $(halcmd getp hm2_5i25.0.io_error) gpio017 $(halcmd getp hm2_sim.0.io.017.out)"; }
halcmd loadrt threads name1=thread period1=1000000
halcmd loadrt hostmot2
halcmd loadrt hm2_sim board=5i25
halcmd setp hm2_5i25.0.watchdog.timeout_ns 4000000000
halcmd setp hm2_5i25.0.gpio.017.is_output TRUE
halcmd addf hm2_5i25.0.read thread
halcmd addf hm2_5i25.0.write thread
halcmd start
sleep 0.3
show running
halcmd setp hm2_sim.0.bus-error TRUE
sleep 0.3
halcmd setp hm2_5i25.0.gpio.017.out TRUE
sleep 0.3
show "bus down"
halcmd setp hm2_sim.0.bus-error FALSE
sleep 0.3
show "bus repaired"
halcmd setp hm2_5i25.0.io_error FALSE
sleep 0.3
show "io_error cleared"
halrun -U
