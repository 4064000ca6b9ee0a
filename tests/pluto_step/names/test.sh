# The names and defaults; the upload checked by the model's config-sum; outputs word
# bits 0-13 plus the watchdog bit 14; inputs word bits 0-15 (bit 16 is not an input).
. ../../helpers/pluto-firmware.sh
pluto_firmware pluto_step.rbf
halcmd -f names.hal
echo "exit $?"
[ "$(halcmd getp sim-parport.0.pluto.config-sum)" = "$PLUTO_SUM" ] && echo "config-sum ok"
halrun -U
pluto_no_firmware pluto_step.rbf
