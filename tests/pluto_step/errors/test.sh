. ../../helpers/pluto-firmware.sh
load() {
	halcmd loadrt pluto_step "$@" >"$TEST_TMPDIR/msg" 2>&1
	rc=$?
	sed 's/(comp [0-9]*)/(comp N)/g' "$TEST_TMPDIR/msg"	# ids differ between flavors
	echo "exit $rc"
}
halcmd loadrt sim_parport io=0x1000,0x1100,0x1200 board=pluto_step,none,pluto_step
halcmd setp sim-parport.2.pluto.epp-timeout 1
pluto_no_firmware pluto_step.rbf
load ioaddr=0x1000
pluto_firmware pluto_step.rbf 19894
load ioaddr=0x1000
pluto_firmware pluto_step.rbf
load ioaddr=0x1000 speedrange=4
load ioaddr=0x1000 speedrange=-1
load ioaddr=-5
load ioaddr=0x1000 watchdog=2
load ioaddr=0x1100
load ioaddr=0x1200
halcmd list comp
load ioaddr=0x1000 ioaddr_hi=-1 speedrange=3
halcmd list comp
echo "ecr $(halcmd getp sim-parport.0.ecr)"
halrun -U
pluto_no_firmware pluto_step.rbf
