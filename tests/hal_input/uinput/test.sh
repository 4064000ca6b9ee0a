# hal_input on a virtual pendant made with uinput (hal_testdev uinput, needs-devices:
# the kernel-test VM's cases/40-devices.sh, or a host with a writable /dev/uinput):
# the pins follow keys, absolute and relative axes; an LED pin reaches the device; a
# second reader of the device gets the events, and none while hal_input holds it with
# '+' (EVIOCGRAB); the device unplugged is reported, its keys read released, and the
# same device plugged again is taken up; the HAL's memory is returned at the end.
. ../../helpers/testdev.sh
# second_reader: the number of events another reader of the device got while the
# test sends a button press and release and hal_input takes them up
second_reader() {
	rm -f "$T/rctl"; mkfifo "$T/rctl"
	hal_testdev read "$node" <"$T/rctl" >"$T/reader.out" 2>&1 &
	r=$!
	exec 4>"$T/rctl"
	wait_for "$T/reader.out" reading || return 1
	echo "key 259 1" >&3; wait_pin input.0.btn-3 TRUE
	echo "key 259 0" >&3; wait_pin input.0.btn-3 FALSE
	exec 4>&-
	wait $r
	cat "$T/reader.out" | grep events
}
testdev_start uinput "hal-test pendant"
halcmd loadrt threads name1=t period1=1000000    # keeps the session between commands
before=$(memory)
halcmd loadusr -Wn hal_input sh -c "exec hal_input 'hal-test pendant' 2>$T/input.err"
echo "loadusr: $?"
halcmd -s show pin input.0
halcmd -s show param input.0 | grep -E 'abs-y|rel-dial-(scale|precision)|led'
echo "key 257 1" >&3
wait_pin input.0.btn-1 TRUE && echo "btn-1 $(halcmd getp input.0.btn-1) btn-1-not $(halcmd getp input.0.btn-1-not)"
echo "key 257 0" >&3
wait_pin input.0.btn-1 FALSE && echo "released: btn-1-not $(halcmd getp input.0.btn-1-not)"
echo "abs 1 1023" >&3
wait_pin input.0.abs-y-counts 1023 && echo "abs-y 1023: position $(halcmd getp input.0.abs-y-position)"
echo "abs 1 0" >&3
wait_pin input.0.abs-y-counts 0 && echo "abs-y 0: position $(halcmd getp input.0.abs-y-position)"
echo "abs 0 -512" >&3
wait_pin input.0.abs-x-counts -512 && echo "abs-x -512: position $(halcmd getp input.0.abs-x-position)"
halcmd setp input.0.rel-dial-scale 4
echo "rel 7 5" >&3
echo "rel 7 -2" >&3
wait_pin input.0.rel-dial-counts 3 && echo "rel-dial +5 -2: counts 3, position $(halcmd getp input.0.rel-dial-position)"
halcmd setp input.0.rel-dial-reset 1
wait_pin input.0.rel-dial-counts 0 && echo "rel-dial reset: counts 0"
halcmd setp input.0.rel-dial-reset 0
halcmd setp input.0.led-misc 1
wait_for "$T/dev.out" "led 8 1" && echo "led-misc TRUE reached the device"
halcmd setp input.0.led-misc-invert 1
wait_for "$T/dev.out" "led 8 0" && echo "led-misc-invert: the device's LED off"
echo "not grabbed, the second reader: $(second_reader)"
halcmd unloadusr hal_input
echo "unloadusr: $?"
halcmd loadusr -Wn hal_input sh -c "exec hal_input '+hal-test pendant' 2>$T/input.err"
echo "grabbed, the second reader: $(second_reader)"
# unplugged with a button held
echo "key 258 1" >&3
wait_pin input.0.btn-2 TRUE
echo destroy >&3
wait_for "$T/input.err" "unplugged" || exit 1
sed "s|$node|NODE|" "$T/input.err"
wait_pin input.0.btn-2 FALSE && echo "btn-2 released by the unplug"
halcmd -s show comp hal_input | awk '{ print $2, $3, $5 }'
echo create >&3
wait_for "$T/input.err" "is back" || exit 1
sed -n 's|/dev/input/event[0-9]*|NODE|; /is back/p' "$T/input.err"
echo "key 258 1" >&3
wait_pin input.0.btn-2 TRUE && echo "btn-2 follows the new device"
halcmd unloadusr hal_input
echo "unloadusr: $?"
echo quit >&3
wait $TESTDEV_PID
halcmd -s show pin input.0 | wc -l
[ "$before" = "$(memory)" ] && echo "memory returned" || { echo "memory differs:"; echo "$before"; memory; }
halrun -U
echo "halrun -U: $?"
