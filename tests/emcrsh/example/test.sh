# The emcrsh(1) page's example session, line for line, against configs/sim/mill.ini
# run by "emc" with emcrsh as its display ([DISPLAY]DISPLAY = emcrsh -p 0: the launcher
# starts "emcrsh -p 0 -- -ini INI"). Between lines the script waits for the machine
# (as the person at telnet would): the reset, machine on, each joint homed, the MDI
# move done. The replies must be the page's; SHUTDOWN ends emcrsh, the launcher then
# cleans up and nothing is left.
T=$(mktemp -d "${TEST_TMPDIR:-/tmp}/emcrsh.XXXXXX")
trap 'rm -rf "$T"' EXIT
export EMC_LOCK_FILE="$T/emc.lock" EMC_RC_FILE="$T/emcrc"
cp -r ../../../configs/sim "$T/cfg" || exit 1
ini=$T/cfg/mill.ini
awk '{ print } /^\[DISPLAY\]$/ { print "DISPLAY = emcrsh -p 0" }' ../../../configs/sim/mill.ini > "$ini" || exit 1
: > "$T/emc.out"
emc "$ini" > "$T/emc.out" 2>&1 < /dev/null &
pid=$!
. ../../../demo/wait-output.sh
port=$(wait_output "$T/emc.out" $pid 60 's/^emcrsh: listening on port \([0-9]*\)$/\1/p') || {
	echo "emc with emcrsh did not come up:"
	cat "$T/emc.out"
	kill -TERM $pid 2>/dev/null
	wait $pid
	exit 1
}
pause() {
	emcbus -ini "$ini" wait "$@" > /dev/null 2>> "$T/wait.err" || echo "wait $*: failed" >> "$T/wait.err"
}
{
	echo "hello EMC user-typing-at-telnet 1.0"
	echo "set enable EMCTOO"
	echo "set mode manual"
	echo "set estop off"
	pause task.state ESTOP_RESET 30
	echo "set machine on"
	pause task.state ON 30
	echo "set home 0"
	pause joint.0.homed 1 120
	echo "set home 1"
	pause joint.1.homed 1 120
	echo "set home 2"
	pause joint.2.homed 1 120
	echo "set mode mdi"
	echo "set mdi g0x1"
	pause axis.x.pos_fb 1.000000 120
	emcbus -ini "$ini" status axis.x.pos_fb task.interp > "$T/pos" 2>&1
	echo "shutdown"
} | rsh_client 127.0.0.1 "$port"
wait $pid
echo "emc exit $?"
cat "$T/wait.err" "$T/pos"
if [ "$HAL_TEST_FLAVOR" = kernel ]; then
	echo "left $(grep -c '^hal_lib ' /proc/modules)"
else
	echo "left $(ls /dev/shm | grep -c -- "-${RTAPI_INSTANCE:-0}-")"
fi
