. ../../helpers/pluto-firmware.sh
pluto_firmware pluto_servo.rbf
halrun -f io.hal
echo "exit $?"
pluto_no_firmware pluto_servo.rbf
