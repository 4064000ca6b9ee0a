# The names and defaults, and the upload as the model saw it: 19895 bytes x 8 clocks
# and the checksum of the reassembled bytes equal to the image's (order, bit order).
. ../../helpers/pluto-firmware.sh
pluto_firmware pluto_servo.rbf
halcmd -f names.hal
echo "exit $?"
[ "$(halcmd getp sim-parport.0.pluto.config-sum)" = "$PLUTO_SUM" ] && echo "config-sum ok"
halrun -U
pluto_no_firmware pluto_servo.rbf
