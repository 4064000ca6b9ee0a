/* SPDX-License-Identifier: GPL-2.0-or-later */
/* limit3.comp - limit3(9): follow in within [min, max] with |velocity| <= maxv and
 * |acceleration| <= maxa. Each period plans against the target and against both limits,
 * each with its own velocity (LinuxCNC's limit3 does the same): aim for the fastest
 * velocity from which the output can still stop on the moving target, and never faster
 * toward min or max than still allows stopping at the moving limit; then change the
 * velocity by at most maxa * period, always, so a limit that jumps inside the output is
 * reached at maxa rather than by an acceleration step. */
component limit3 """Limit the output signal to fall between min and max, limit its slew rate to
less than maxv per second, and limit its second derivative to less than maxa per second squared.
When the signal is a position, this means that the position, velocity, and acceleration are
limited.""";
pin in float in;
pin in bit enable = TRUE "1: out follows in, 0: out returns to 0 (always per constraints)";
pin out float out;
pin in bit load "When TRUE, immediately set out to in, ignoring maxv and maxa";
pin in float min_ = -1e20;
pin in float max_ = 1e20;
pin in float maxv = 1e20;
pin in float maxa = 1e20;
variable double vel;		/* out velocity of the previous period, units/s */
variable double last_target;	/* clamped goal of the previous period, for its velocity */
variable double last_min;	/* min and max of the previous period, for their velocities */
variable double last_max;
variable int first = 1;
function _;
license "GPL";
;;
static double clampd(double v, double lo, double hi)
{
	return v > hi ? hi : v < lo ? lo : v;
}

/* Fastest speed toward something d away from which braking by a*dt per period, in
 * whole periods, stops exactly there: moving n+1 more periods at v, v - a*dt, ...,
 * v - n*a*dt covers (n+1)*v*dt - a*dt*dt*n*(n+1)/2 = |d|, with n the most whole braking
 * periods that fit. The last period then lands on the point exactly. Signed like d. */
static double approach_vel(double d, double a, double dt)
{
	double x = fabs(d), adt2 = a * dt * dt, n, v;

	if (!(adt2 > 0))
		return d / dt;
	n = floor((sqrt(1 + 8 * x / adt2) - 1) / 2);
	v = (x / dt + a * dt * n * (n + 1) / 2) / (n + 1);
	return d < 0 ? -v : v;
}

FUNCTION(_)
{
	double dt = fperiod, a = maxa, vmax = maxv;
	double lo = min_, hi = max_;
	double target = clampd(enable ? in : 0.0, lo, hi);
	double target_vel, lo_vel, hi_vel, err, step_v, v_want, v_new;

	if (first || load) {
		first = 0;
		last_target = target;
		last_min = lo;
		last_max = hi;
		if (load) {
			out = in;
			vel = 0;
			return;
		}
	}
	target_vel = (target - last_target) / dt;
	lo_vel = (lo - last_min) / dt;
	hi_vel = (hi - last_max) / dt;
	last_target = target;
	last_min = lo;
	last_max = hi;
	err = target - out;
	step_v = err / dt;
	/* close enough to land on the target this period and ride along with it next period */
	if (fabs(step_v - vel) <= a * dt && fabs(step_v - target_vel) <= a * dt
	    && fabs(step_v) <= vmax) {
		vel = step_v;
		out = target;
		return;
	}
	/* the target (and each limit) moved its own velocity times dt since the last period,
	 * which the feed-forward of that velocity covers; plan the rest */
	v_want = target_vel + approach_vel(err - target_vel * dt, a, dt);
	/* never so fast toward a limit that the output could not stop at it */
	v_want = clampd(v_want, lo_vel + approach_vel(lo - out - lo_vel * dt, a, dt),
			hi_vel + approach_vel(hi - out - hi_vel * dt, a, dt));
	v_want = clampd(v_want, -vmax, vmax);
	v_new = clampd(v_want, vel - a * dt, vel + a * dt);
	vel = v_new;
	out = out + v_new * dt;
}
