# shuttlexpress on a virtual ShuttleXpress made with uhid (hal_testdev uhid: USB
# 0b33:0020, its 5-byte report; needs-devices: the kernel-test VM's cases/40-devices.sh,
# or a host with a writable /dev/uhid). Found by probing /dev/hidraw* and when named;
# a device that is not a ShuttleXpress is refused; the buttons, the jog counter
# (the first report sets the reference; 255 -> 0 counts +1) and the spring wheel reach
# the pins; the device unplugged is reported and the pins keep their values; the HAL's
# memory is returned at the end.
. ../../helpers/testdev.sh
pins() {
	printf 'buttons'
	for b in 0 1 2 3 4; do printf ' %s' "$(halcmd getp shuttlexpress.0.button-$b)"; done
	echo " counts $(halcmd getp shuttlexpress.0.counts) spring $(halcmd getp shuttlexpress.0.spring-wheel-s32) $(halcmd getp shuttlexpress.0.spring-wheel-f)"
}
testdev_start uhid
halcmd loadrt threads name1=t period1=1000000    # keeps the session between commands
before=$(memory)
# probing every /dev/hidraw*: ours is the only ShuttleXpress
halcmd loadusr -Wn shuttlexpress sh -c "exec shuttlexpress 2>$T/sx.err"
echo "loadusr (probing): $?"
halcmd -s show pin shuttlexpress.0
echo "report 0 10 0 0 0" >&3       # the jog reference
echo "report 0 11 0 0x10 0" >&3    # jog +1, button 0
wait_pin shuttlexpress.0.button-0 TRUE && pins
echo "report 3 13 0 0x60 0" >&3    # jog +2, buttons 1 and 2, spring +3
wait_pin shuttlexpress.0.counts 3 && pins
echo "report 0xf9 255 0 0x80 1" >&3  # jog -14, buttons 3 and 4, spring -7
wait_pin shuttlexpress.0.counts -11 && pins
echo "report 0 0 0 0 0" >&3        # 255 -> 0 is +1
wait_pin shuttlexpress.0.counts -10 && pins
echo "button-0-not $(halcmd getp shuttlexpress.0.button-0-not)"
halcmd unloadusr shuttlexpress
echo "unloadusr: $?"
# named: the same device; a hidraw device that is not a ShuttleXpress is refused
halcmd loadusr -Wn shuttlexpress sh -c "exec shuttlexpress $node 2>$T/sx.err"
echo "loadusr (named): $?"
echo "report 0 40 0 0 0" >&3
echo "report 0 42 0 0x10 0" >&3
wait_pin shuttlexpress.0.counts 2 && pins
shuttlexpress /dev/null 2>&1
echo "not a ShuttleXpress: exit $?"
echo destroy >&3
wait_for "$T/sx.err" "keep their last values" || exit 1
sed "s|$node|NODE|" "$T/sx.err"
pins
halcmd -s show comp shuttlexpress | awk '{ print $2, $3, $5 }'
halcmd unloadusr shuttlexpress
echo "unloadusr: $?"
[ "$before" = "$(memory)" ] && echo "memory returned" || { echo "memory differs:"; echo "$before"; memory; }
echo quit >&3
wait $TESTDEV_PID
halrun -U
echo "halrun -U: $?"
