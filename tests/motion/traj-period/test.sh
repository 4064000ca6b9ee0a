# A trajectory period of 5 servo periods (motion.md 2, 3: the interpolation rate is
# traj/servo): X's coarse-pos-cmd (the planner output) and pos-cmd (the interpolated
# command) sampled every servo period. The planner point may change only every 5th
# period; the interpolated command stays within the joint's limits and ends exactly
# at the target. (LinuxCNC uses no base thread here; servo 1 ms, traj 5 ms.)
. ../lib.sh
motion_load 3 traj_period_nsec=5000000
halcmd loadrt sampler depth=8000 cfg=ff || exit 1
halcmd net coarse joint.0.coarse-pos-cmd sampler.0.pin.0 || exit 1
halcmd loadrt scale || exit 1	# x 1e6: the sampler prints six decimals
halcmd net x joint.0.pos-cmd scale.0.in || exit 1
halcmd setp scale.0.gain 1000000 || exit 1
halcmd net xs scale.0.out sampler.0.pin.1 || exit 1
halcmd addf scale.0 servo-thread || exit 1
halcmd addf sampler.0 servo-thread || exit 1
halcmd start || exit 1
motion_config 3 10 100
motion_coord
capture_start "$T/traj.txt"
motcmd line 3 0 0 8 100 || exit 1
motcmd wait-inpos 5 || exit 1
capture_stop
# the periods between changes of the planner point: all multiples of 5
awk '{ if (n && $1 != pc) { if (last && (n - last) % 5) bad++; if (last && n - last == 5) five++; last = n }
       pc = $1; n++ }
     END { printf "planner point changes 5 periods apart: %s; other gaps not multiples of 5: %d\n",
                  (five > 50 ? "yes" : "NO (" five ")"), bad }' "$T/traj.txt"
awk '{ print $2 }' "$T/traj.txt" >"$T/x.txt"
echo "interpolated X: $(motion_analyze 0.001 <"$T/x.txt") (limits 10, 100)" |
	awk '{ ok = $4 <= 10 * (1 + 1e-6) && $6 <= 100 * 1.0001
	       printf "interpolated X within the limits: %s, final %s\n", ok ? "yes" : "NO (" $0 ")", $8 }'
motcmd errors
halrun -U
