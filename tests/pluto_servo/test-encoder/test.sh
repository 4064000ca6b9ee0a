. ../../helpers/pluto-firmware.sh
pluto_firmware pluto_servo.rbf
halcmd -f setup.hal || echo "setup failed"
step() {	# A B Z levels for one write, then the count
	halcmd setp pluto-servo.dout.00 $1
	halcmd setp pluto-servo.dout.01 $2
	halcmd setp pluto-servo.dout.02 $3
	sleep 0.05
	echo "A=$1 B=$2 Z=$3: count $(halcmd getp pluto-servo.encoder.0.count)"
}
echo "outputs $(halcmd getp sim-parport.0.pluto.outputs)" \
	"watchdog-enabled $(halcmd getp sim-parport.0.pluto.watchdog-enabled)"
step 1 0 0
step 1 1 0
step 0 1 0
step 0 0 0
step 0 1 0
halcmd setp pluto-servo.encoder.0.index-enable 1
step 0 1 1
step 0 0 0
echo "index-enable $(halcmd getp pluto-servo.encoder.0.index-enable)"
halrun -U
pluto_no_firmware pluto_servo.rbf
