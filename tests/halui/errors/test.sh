# Bad command lines and INI values stop halui with one line naming the file and line
# (exit 1; usage errors exit 2); without task halui still serves its pins and
# commands are not sent.
. ../lib.sh
run() {
	halui "$@" 2>&1 | sed "s|$T/||g"
	echo "exit $(halui "$@" >/dev/null 2>&1; echo $?)"
}
# 65 commands in the [HALUI] section (a second [HALUI] block would not be read)
awk '{ print } /^\[HALUI\]/ { for (i = 0; i < 63; i++) print "MDI_COMMAND = G0 X" i }' "$INI" >"$T/many.ini"
run -ini "$T/many.ini"
sed 's/^MAX_FEED_OVERRIDE = 1.5/MAX_FEED_OVERRIDE = fast/' "$INI" >"$T/feed.ini"
run -ini "$T/feed.ini"
sed 's/^MAX_SPINDLE_OVERRIDE = 1.2/MAX_SPINDLE_OVERRIDE = 0.4/' "$INI" >"$T/spindle.ini"
run -ini "$T/spindle.ini"
sed 's/^MDI_COMMAND = G0 X12 Y-3 Z0/MDI_COMMAND =/' "$INI" >"$T/empty.ini"
run -ini "$T/empty.ini"
run -ini "$T/missing.ini"
run -bogus
run
# no task on the bus: the pins are there with their defaults, presses go nowhere
halcmd loadusr -Wn halui halui -ini "$INI" -bus "$T/nobody.sock" || exit 1
press estop.reset
press machine.on
echo "no task: estop $(pin estop.is-activated) on $(pin machine.is-on) count-enable $(pin feed-override.count-enable) scale $(pin feed-override.scale) deadband $(pin joint.jog-deadband)"
halcmd unloadusr halui
