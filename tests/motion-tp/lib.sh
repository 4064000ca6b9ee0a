# lib.sh - sourced by the motion-tp cases' test.sh (cwd: the case directory), on top
# of ../motion/lib.sh (motion_load, motion_config, capture_start/stop).
# tp_sample: joints 0 and 1 (X and Y, trivkins) pos-cmd x 1e6 into sampler 0,
#   every servo period.
# tp_square_run FILE TERM [TOL]: COORD mode, the 5 x 5 square at F 8 under
#   term-cond TERM, captured into FILE.
# tp_analyze DT VMAX AMAX TOL < samples: per-axis velocity/acceleration limits, the
#   distance from the programmed square, whether it stopped on each corner (a sample
#   within 2e-5 of it at a speed below 2 a dt), the final point.
. ../../motion/lib.sh

tp_sample() {
	halcmd loadrt scale count=2 || exit 1
	halcmd loadrt sampler depth=16000 cfg=ff || exit 1
	for j in 0 1; do
		halcmd net sampled$j joint.$j.pos-cmd scale.$j.in || exit 1
		halcmd setp scale.$j.gain 1000000 || exit 1
		halcmd net scaled$j scale.$j.out sampler.0.pin.$j || exit 1
		halcmd addf scale.$j servo-thread || exit 1
	done
	halcmd addf sampler.0 servo-thread || exit 1
}

tp_square_run() {
	motcmd enable || exit 1
	motcmd coord || exit 1
	motcmd wait-state coord 10 || exit 1
	motcmd term-cond "$2" $3 || exit 1
	capture_start "$1"
	cat >square.cmd <<CMDS
line 5 0 0 8 100
line 5 5 0 8 100
line 0 5 0 8 100
line 0 0 0 8 100
CMDS
	motcmd -f square.cmd || exit 1
	sleep 0.2
	motcmd wait-inpos 30 || exit 1
	capture_stop
}

tp_analyze() {
	awk -v dt="$1" -v vlim="$2" -v alim="$3" -v tol="$4" '
	function segd(px, py, ax, ay, bx, by,   dx, dy, t, l2, ex, ey) {
		dx = bx - ax; dy = by - ay; l2 = dx * dx + dy * dy
		t = ((px - ax) * dx + (py - ay) * dy) / l2
		if (t < 0) t = 0; if (t > 1) t = 1
		ex = px - ax - t * dx; ey = py - ay - t * dy
		return sqrt(ex * ex + ey * ey)
	}
	function abs(v) { return v < 0 ? -v : v }
	BEGIN { cx[0] = 5; cy[0] = 0; cx[1] = 5; cy[1] = 5; cx[2] = 0; cy[2] = 5 }
	{ x = $1 / 1e6; y = $2 / 1e6
	  d = segd(x, y, 0, 0, 5, 0); e = segd(x, y, 5, 0, 5, 5); if (e < d) d = e
	  e = segd(x, y, 5, 5, 0, 5); if (e < d) d = e; e = segd(x, y, 0, 5, 0, 0); if (e < d) d = e
	  if (d > dev) dev = d
	  # nearest sample to each corner and the speed there: at a stop the cubic
	  # interpolator passes within a fraction of a*dt^2 of the corner, at rest
	  sp = n > 0 ? sqrt((x - px) ^ 2 + (y - py) ^ 2) / dt : 0
	  for (c = 0; c < 3; c++) { cd = sqrt((x - cx[c]) ^ 2 + (y - cy[c]) ^ 2)
	    if (n == 0 || cd < best[c]) { best[c] = cd; bsp[c] = sp } }
	  if (n > 0) { vx = (x - px) / dt; vy = (y - py) / dt
	    if (abs(vx) > vmax) vmax = abs(vx); if (abs(vy) > vmax) vmax = abs(vy)
	    if (n > 1) { ax = abs(vx - pvx) / dt; ay = abs(vy - pvy) / dt
	      if (ax > amax) amax = ax; if (ay > amax) amax = ay }
	    pvx = vx; pvy = vy }
	  px = x; py = y; n++ }
	END {
	  printf "velocity within %g: %s\n", vlim, vmax <= vlim * (1 + 1e-6) ? "yes" : "NO (" vmax ")"
	  printf "acceleration within %g: %s\n", alim, amax <= alim * (1 + 1e-4) ? "yes" : "NO (" amax ")"
	  printf "within %g of the square: %s\n", tol, dev <= tol + 2e-6 ? "yes" : "NO (" dev ")"
	  for (c = 0; c < 3; c++) on[c] = best[c] < 2e-5 && bsp[c] < 2 * alim * dt
	  printf "stopped on the corners: %d %d %d\n", on[0], on[1], on[2]
	  printf "final %.6f %.6f\n", px, py }'
}
