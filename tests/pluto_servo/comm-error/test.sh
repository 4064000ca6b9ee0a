. ../../helpers/pluto-firmware.sh
pluto_firmware pluto_servo.rbf
halcmd -f setup.hal || echo "setup failed"
sleep 0.1
echo "running: outputs $(halcmd getp sim-parport.0.pluto.outputs)" \
	"bitten $(halcmd getp sim-parport.0.pluto.watchdog-bitten)"
halcmd setp sim-parport.0.pluto.epp-timeout 1
sleep 0.1
halcmd setp pluto-servo.dout.01 1	# not written while the error stands
sleep 0.1
[ "$(halcmd getp pluto-servo.communication-error)" -gt 0 ] && echo "communication-error counted"
echo "frozen: outputs $(halcmd getp sim-parport.0.pluto.outputs)" \
	"bitten $(halcmd getp sim-parport.0.pluto.watchdog-bitten)"
halcmd setp sim-parport.0.pluto.epp-timeout 0
halcmd setp pluto-servo.communication-error 0
sleep 0.1
echo "resumed: outputs $(halcmd getp sim-parport.0.pluto.outputs)" \
	"bitten $(halcmd getp sim-parport.0.pluto.watchdog-bitten)" \
	"errors $(halcmd getp pluto-servo.communication-error)"
halrun -U
pluto_no_firmware pluto_servo.rbf
