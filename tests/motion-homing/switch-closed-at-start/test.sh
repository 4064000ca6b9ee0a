# The switch is closed where the joint stands (above -1.0): homing first backs off at
# -SEARCH_VEL until it opens, then searches; HOME_OFFSET 1, HOME 1.5: the rising edge
# at -1.0 reads 1, so HOME is motor position -0.5. The final move runs at
# HOME_FINAL_VEL 0.5: its sampled speed never exceeds 0.5 units/s.
. ../lib.sh
homing_machine 1
halcmd setp comp.0.in0 -1.0
halcmd start
joint_limits 0
motcmd set-joint-homing 0 1 1.5 0.5 2 0.5 0 0 || exit 1
motcmd enable || exit 1
motcmd home 0 || exit 1
motcmd wait-homed 30 || exit 1
motcmd errors
stop_and_sample "$TEST_TMPDIR/s"
echo "home-state: $(states "$TEST_TMPDIR/s" 1)"
awk '$1 == 21 && NR > 1 { v = ($2 - p) / 0.001; if (v < 0) v = -v; if (v > m) m = v } { p = $2 }
     END { printf "final move speed %s\n", (m > 0.49 && m < 0.5000001) ? "0.5" : m }' "$TEST_TMPDIR/s"
echo "joint.0.homed $(halcmd getp joint.0.homed)"
pos joint.0.pos-cmd 3
pos joint.0.motor-pos-cmd 2
halrun -U
