# The inihal pins (ini.*): created by milltask with the INI values; a changed pin
# reaches motion (its parameters in the status, f-error-lim, the speeds a move
# reaches, homing to the new HOME).
. ../lib.sh
task_start
echo "-- pins with the INI values"
for p in ini.0.max_velocity ini.0.ferror ini.0.min_ferror ini.0.home_sequence ini.2.max_acceleration \
	ini.x.max_limit ini.z.max_velocity ini.traj_max_velocity ini.traj_max_acceleration \
	ini.traj_arc_blend_enable ini.traj_arc_blend_optimization_depth ini.traj_arc_blend_tangent_kink_ratio; do
	echo "$p $(halcmd getp $p)"
done
machine_ready
echo "-- ferror: ini.0.ferror 3, ini.0.min_ferror 0.25"
halcmd setp ini.0.ferror 3 || exit 1
halcmd setp ini.0.min_ferror 0.25 || exit 1
bus wait joint.0.min_ferror 0.250000 5 || exit 1
bus status joint.0.max_ferror joint.0.min_ferror joint.1.max_ferror
echo "f-error-lim $(halcmd getp joint.0.f-error-lim)"
echo "-- velocity: joint 0 and axis X 20, traj 5"
halcmd setp ini.0.max_velocity 20 || exit 1
halcmd setp ini.x.max_velocity 20 || exit 1
bus wait axis.x.max_velocity 20.000000 5 || exit 1
bus status joint.0.max_velocity axis.x.max_velocity traj.max_velocity
sample_start "$T/samples"
bus mdi G0 X10 || exit 1
halcmd setp ini.traj_max_velocity 5 || exit 1
bus wait traj.max_velocity 5.000000 5 || exit 1
bus mdi G1 X0 F3000 || exit 1
sample_stop
# X speed per servo period: out (X rising, the rapid) and back (the feed)
awk '{ if (n++) { d = ($1 - x) * 1000; if (d > up) up = d; if (-d > down) down = -d } x = $1 }
	END { printf "rapid out %s, feed back %s\n", (up > 19 && up <= 20.001) ? "at 20" : "at " up,
		(down > 4.9 && down <= 5.001) ? "at 5" : "at " down }' "$T/samples"
echo "-- home: ini.0.home 5, ini.0.home_offset 1"
halcmd setp ini.0.home 5 || exit 1
halcmd setp ini.0.home_offset 1 || exit 1
sleep 0.2
bus mode manual || exit 1
bus teleop 0 || exit 1
bus wait traj.mode FREE 5 || exit 1
bus unhome 0 || exit 1
bus home 0 || exit 1
bus wait joint.0.homed 1 5 || exit 1
bus status joint.0.pos_fb
task_stop
