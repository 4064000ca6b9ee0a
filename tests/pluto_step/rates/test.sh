# Rate register = steps/s x 1.6 us x 2^11 (pluto.md §5.3): 20 kHz -> 65.536 -> 66;
# -10 kHz -> -32.768 -> -33; 1 MHz is above 312.5 kHz -> 1024; disabled -> 0. First with the
# loop gain (debug-2) at 0, feed-forward only: exact. Then with the gain at 0.5 the
# feedback follows the command; host time drives the model (and a thread may be
# late, in qemu by milliseconds), so those checks have margins. (Counts are followed
# through the 21-bit position register: at most 512 steps between reads, a 25 ms gap
# at 20 kHz; the thread is not stopped before the last phase.)
. ../../helpers/pluto-firmware.sh
pluto_firmware pluto_step.rbf
halcmd -f setup.hal || echo "setup failed"
sleep 0.1
near() {	# NAME VALUE LOW HIGH
	awk -v n="$1" -v v="$2" -v lo="$3" -v hi="$4" \
		'BEGIN { print n, (v >= lo && v <= hi) ? "ok" : "out of range: " v }'
}
for i in 0 1 2 3; do echo "rate$i $(halcmd getp sim-parport.0.pluto.stepgen.$i.rate)"; done
halcmd setp pluto-step.debug-2 0.5
sleep 0.3
halcmd stop
cmd0=$(halcmd getp pluto-step.stepgen.0.position-cmd)
fb0=$(halcmd getp pluto-step.stepgen.0.position-fb)
steps0=$(halcmd getp sim-parport.0.pluto.stepgen.0.steps)
counts0=$(halcmd getp pluto-step.stepgen.0.counts)
near fb0-cmd0 "$(awk "BEGIN { print $fb0 - $cmd0 }")" -600 600
near counts0-steps0 "$((counts0 - steps0))" -20 20	# the write comes later than the read
fb1=$(halcmd getp pluto-step.stepgen.1.position-fb)
cmd1=$(halcmd getp pluto-step.stepgen.1.position-cmd)
near fb1-cmd1 "$(awk "BEGIN { print $fb1 - $cmd1 }")" -300 300
near velocity-fb0 "$(halcmd getp pluto-step.stepgen.0.velocity-fb)" 1 1e9
echo "fb3 $(halcmd getp pluto-step.stepgen.3.position-fb)"
halrun -U
pluto_no_firmware pluto_step.rbf
