# gs2_vfd against gs2_sim, a libmodbus RTU server on a pseudo-terminal: every pin
# follows the drive's status registers, speed/run/direction commands arrive, a drive
# that stops answering is counted (error-count, retval) and found again, a pulled
# cable (the pty closed and made anew) is reopened, unloadusr stops the spindle.
T=${TEST_TMPDIR:-/tmp}
wait_for() {   # FILE PATTERN: up to 20 s
	i=0
	while ! grep -q "$2" "$1" 2>/dev/null; do
		i=$((i + 1)); [ $i -gt 400 ] && { echo "timed out waiting for '$2' in $1"; cat "$1"; return 1; }
		sleep 0.05
	done
}
wait_pin() {   # NAME VALUE
	i=0
	while [ "$(halcmd getp "$1")" != "$2" ]; do
		i=$((i + 1)); [ $i -gt 400 ] && { echo "timed out waiting for $1 = $2 (is $(halcmd getp "$1"))"; return 1; }
		sleep 0.05
	done
}
rm -f "$T/ctl"; mkfifo "$T/ctl"
gs2_sim "$T/gs2" <"$T/ctl" >"$T/sim.out" 2>&1 &
sim=$!
exec 3>"$T/ctl"
wait_for "$T/sim.out" ready || exit 1
# the status block 0x2100..0x210C
for r in "0x2100 4" "0x2101 163" "0x2104 35" "0x2105 3251" "0x2106 2301" "0x2107 1725" \
	"0x2108 0x5678" "0x2109 1" "0x210A 855" "0x210B 123" "0x210C 104"; do
	echo "set $r" >&3
done
halcmd loadusr -Wn spindle sh -c "exec gs2_vfd -d $T/gs2 -n spindle -r 38400 -t 1 2>$T/gs2.err"
echo "loadusr: $?"
halcmd setp spindle.loop-time 0.02
wait_pin spindle.firmware-revision 104
halcmd -s show pin spindle
halcmd -s show param spindle | grep -v loop-time
# speed commands: 865 RPM at 60 Hz / 1730 RPM is 30.0 Hz = 300 in 0.1 Hz
halcmd setp spindle.speed-command 865
halcmd setp spindle.spindle-fwd 1
halcmd setp spindle.spindle-on 1
wait_for "$T/sim.out" "write 0x091B 1" || exit 1
grep '^write' "$T/sim.out"
wait_pin spindle.at-speed TRUE
echo "frequency-out $(halcmd getp spindle.frequency-out), is-stopped $(halcmd getp spindle.is-stopped)"
# the drive stops answering three requests: three timeouts, then it is found again
echo "drop 3" >&3
wait_pin spindle.error-count 3
wait_for "$T/gs2.err" "answers again" || exit 1
echo "retval $(halcmd getp spindle.retval)"
sed "s|$T|T|g" "$T/gs2.err"
# the cable is pulled and put back
echo "hangup" >&3
i=0; while [ "$(halcmd getp spindle.error-count)" = 3 ] && [ $i -lt 400 ]; do i=$((i + 1)); sleep 0.05; done
echo "set 0x210C 105" >&3
wait_pin spindle.firmware-revision 105 && echo "reconnected after the hangup"
halcmd unloadusr spindle
echo "unloadusr: $?"
wait_for "$T/sim.out" "write 0x091B 0" && echo "spindle stopped on exit"
echo quit >&3
wait $sim
halrun -U
