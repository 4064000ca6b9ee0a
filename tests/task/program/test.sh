# A program runs to its end in AUTO mode; the joint positions sampled every servo
# period stay on the programmed path (checkresult), and the program ends at its
# last point with the interpreter IDLE.
. ../lib.sh
task_start
machine_ready
sample_start "$T/samples"
bus mode auto || exit 1
bus open "$PWD/square.ngc" || exit 1
bus run || exit 1
bus wait task.interp IDLE 30 || exit 1
sample_stop
joints
bus status task.interp task.file | sed "s|$PWD/||"
echo "samples $(wc -l < "$T/samples" | awk '$1 > 500 { print "many" }')"
# every sample on one of the segments (axis-aligned square at Z0, the diagonal
# X=Y with Z=-X/4, the Z retract at X=Y=20)
awk '
function abs(v) { return v < 0 ? -v : v }
{ x = $1; y = $2; z = $3; e = 0.02
  on = 0
  if (abs(z) < e && x > -e && x < 20 + e && (abs(y) < e || abs(y - 20) < e)) on = 1
  if (abs(z) < e && y > -e && y < 20 + e && (abs(x) < e || abs(x - 20) < e)) on = 1
  if (abs(x - y) < e && abs(z + x / 4) < e) on = 1
  if (abs(x - 20) < e && abs(y - 20) < e && z > -5 - e && z < e) on = 1
  if (!on) { bad++; if (bad < 4) print "off path:", x, y, z } }
END { print "off-path samples", bad + 0 }' "$T/samples"
task_stop
