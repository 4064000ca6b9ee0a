# check-step-timing.awk - checks a sampled step/dir waveform (columns: step dir
# counts, one line per make-pulses period) against stepgen's type 0 timing:
#   -v L=steplen -v S=stepspace -v H=dirhold -v D=dirsetup (all in periods)
#   -v FWD=forward steps -v REV=reverse steps -v FINAL=last counts value
# Every pulse is exactly L periods high, at least S low (exactly S at the
# maximum rate, which the case must reach), dir changes exactly H periods after
# the fall (the reversal is pending then) and the next rise comes exactly D later.
function fail(msg) { print "FAIL line " NR ": " msg; bad = 1 }
{
	step = $1; dir = $2; counts = $3
	if (NR > 1) {
		if (step && !prev_step) {			# rising edge
			if (dir) rev++; else fwd++
			if (last_fall && NR - last_fall < S) fail("space " NR - last_fall " < " S)
			if (last_fall && NR - last_fall < minspace) minspace = NR - last_fall
			if (dir_change) {
				if (NR - dir_change != D) fail("dirsetup " NR - dir_change " != " D)
				dir_change = 0
			}
			rise = NR
		}
		if (!step && prev_step) {			# falling edge
			if (NR - rise != L) fail("pulse " NR - rise " periods, not " L)
			last_fall = NR
		}
		if (dir != prev_dir) {
			if (step) fail("dir changed while step is high")
			if (NR - last_fall != H) fail("dirhold " NR - last_fall " != " H)
			dir_change = NR
		}
	}
	prev_step = step; prev_dir = dir
}
BEGIN { minspace = 1000000 }
END {
	if (fwd != FWD) fail(fwd " forward steps, not " FWD)
	if (rev != REV) fail(rev " reverse steps, not " REV)
	if (counts != FINAL) fail("counts ends at " counts ", not " FINAL)
	if (minspace != S) fail("closest pulses " minspace " periods apart, not " S)
	if (!bad) print "ok"
	exit bad
}
