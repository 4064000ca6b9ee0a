# An EPP timeout while running (the 7i43 model's cable pulled): hm2_7i43 says so,
# sets io_error, and hostmot2 stops talking to the board (a GPIO change does not
# reach it). Plugged in again, nothing changes until the user clears io_error; the
# next write() then rewrites every register. (A 4 s watchdog timeout: the pause
# must not make it bite, which would release the pin too.)
set -e
. ../../helpers/hm2-bitfile.sh
show() { echo "$1: io_error $(halcmd getp hm2_7i43.0.io_error) gpio000 $(halcmd getp sim-parport.0.7i43.io.000.out)"; }
hm2_bitfile hm2/7i43/good.BIT 3s400tq144
halcmd loadrt threads name1=thread period1=1000000
halcmd loadrt hostmot2
halcmd loadrt sim_parport io=0x2000 board=7i43
halcmd loadrt hm2_7i43 ioaddr=0x2000 config='"firmware=hm2/7i43/good.BIT num_encoders=0 num_pwmgens=0"'
halcmd setp hm2_7i43.0.watchdog.timeout_ns 4000000000
halcmd setp hm2_7i43.0.gpio.000.is_output TRUE
halcmd addf hm2_7i43.0.read thread
halcmd addf hm2_7i43.0.write thread
halcmd start
sleep 0.3
show running
halcmd setp sim-parport.0.7i43.unplugged TRUE
sleep 0.3
halcmd setp hm2_7i43.0.gpio.000.out TRUE
sleep 0.3
show unplugged
halcmd setp sim-parport.0.7i43.unplugged FALSE
sleep 0.3
show "plugged in"
halcmd setp hm2_7i43.0.io_error FALSE
sleep 0.3
show "io_error cleared"
# the timeout's message (kernel flavor: rtapi.ko's message ring; the simulated
# flavor's rtapi_app writes it to its own stderr, out of the test's reach)
if [ -r /proc/rtapi/messages ]; then
	echo "rtapi messages: $(grep -c 'hm2_7i43.0: EPP timeout on' /proc/rtapi/messages)"
fi
halrun -U
