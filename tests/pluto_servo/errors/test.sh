# Port 0x1000: a Pluto-P; 0x1100: nothing on the cable; 0x1200: a Pluto-P whose EPP
# cycles time out. After every refusal only sim_parport (and hal_parport while it
# holds the port) is loaded; at the end a good load works.
. ../../helpers/pluto-firmware.sh
load() {
	halcmd loadrt pluto_servo "$@" >"$TEST_TMPDIR/msg" 2>&1
	rc=$?
	sed 's/(comp [0-9]*)/(comp N)/g' "$TEST_TMPDIR/msg"	# ids differ between flavors
	echo "exit $rc"
}
halcmd loadrt sim_parport io=0x1000,0x1100,0x1200 board=pluto_servo,none,pluto_servo
halcmd setp sim-parport.2.pluto.epp-timeout 1
pluto_no_firmware pluto_servo.rbf
load ioaddr=0x1000
pluto_firmware pluto_servo.rbf 100
load ioaddr=0x1000
pluto_firmware pluto_servo.rbf
load ioaddr=0
load ioaddr=0x10000
load ioaddr=0x1000 ioaddr_hi=-2
load ioaddr=0x1000 epp_wide=2
load ioaddr=0x1000 watchdog=-1
load ioaddr=0x1000 test_encoder=2
load ioaddr=0x1100
load ioaddr=0x1200
halcmd loadrt hal_parport cfg=0x1000
load ioaddr=0x1000
halcmd unloadrt hal_parport
halcmd list comp
load ioaddr=0x1000
halcmd list comp
halcmd getp sim-parport.0.pluto.configured
halrun -U
pluto_no_firmware pluto_servo.rbf
