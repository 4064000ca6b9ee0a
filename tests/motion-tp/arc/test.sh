# A full circle (R 5 about (5, 0), G3) through motcmd: the X/Y joint positions sampled
# every servo period stay on the true circle (cubic interpolation included) and
# within each joint's MAX_VELOCITY 10 / MAX_ACCELERATION 100; the feed 8 is cut to
# sqrt(0.866 * 100 * 5) = 20.8 > 8, so the circle runs at F.
. ../lib.sh
motion_load 3
tp_sample
halcmd start || exit 1
motion_config 3 10 100
motcmd enable || exit 1
motcmd coord || exit 1
motcmd wait-state coord 10 || exit 1
capture_start circle.txt
motcmd arc 0 0 0 5 0 0 0 0 1 0 8 100 || exit 1
sleep 0.2
motcmd wait-inpos 30 || exit 1
capture_stop
awk -v dt=0.001 '
function abs(v) { return v < 0 ? -v : v }
{ x = $1 / 1e6; y = $2 / 1e6; r = sqrt((x - 5) ^ 2 + y ^ 2)
  if (abs(r - 5) > dev) dev = abs(r - 5)
  if (y > ymax) ymax = y; if (y < ymin) ymin = y
  if (n > 0) { vx = (x - px) / dt; vy = (y - py) / dt; s = sqrt(vx * vx + vy * vy)
    if (s > smax) smax = s; if (abs(vx) > vmax) vmax = abs(vx); if (abs(vy) > vmax) vmax = abs(vy)
    if (n > 1) { a = abs(vx - pvx) / dt; if (a > amax) amax = a; a = abs(vy - pvy) / dt; if (a > amax) amax = a }
    pvx = vx; pvy = vy }
  px = x; py = y; n++ }
END {
  printf "on the circle within 1e-5: %s\n", dev < 1e-5 ? "yes" : "NO (" dev ")"
  printf "went round: %s\n", (ymax > 4.99 && ymin < -4.99) ? "yes" : "NO"
  printf "path speed reaches F 8: %s\n", abs(smax - 8) < 1e-3 ? "yes" : "NO (" smax ")"
  printf "axis velocity within 10: %s\n", vmax <= 10 * (1 + 1e-6) ? "yes" : "NO (" vmax ")"
  printf "axis acceleration within 100: %s\n", amax <= 100 * (1 + 1e-4) ? "yes" : "NO (" amax ")"
  printf "final %.6f %.6f\n", px, py }' <circle.txt
motcmd errors
rm -f circle.txt config.cmd
halrun -U
