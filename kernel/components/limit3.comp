/* SPDX-License-Identifier: GPL-2.0-or-later */
/* limit3.comp - limit3(9): follow in within [min, max] with |velocity| <= maxv and
 * |acceleration| <= maxa: each period, aim for the fastest velocity from which the output can
 * still stop on the (moving) target, and change the velocity by at most maxa * period. */
component limit3 """Limit the output signal to fall between min and max, limit its slew rate to
less than maxv per second, and limit its second derivative to less than maxa per second squared.
When the signal is a position, this means that the position, velocity, and acceleration are
limited.""";
pin in float in;
pin out float out;
pin in bit load "When TRUE, immediately set out to in, ignoring maxv and maxa";
pin in float min_ = -1e20;
pin in float max_ = 1e20;
pin in float maxv = 1e20;
pin in float maxa = 1e20;
variable double vel;		/* out velocity of the previous period, units/s */
variable double last_target;	/* clamped in of the previous period, for the target velocity */
variable int first = 1;
function _;
license "GPL";
;;
static double clampd(double v, double lo, double hi)
{
	return v > hi ? hi : v < lo ? lo : v;
}

FUNCTION(_)
{
	double dt = fperiod, a = maxa, vmax = maxv;
	double target = clampd(in, min_, max_);
	double target_vel, err, step_v, v_rel, v_want, v_new, pos;

	if (first || load) {
		first = 0;
		last_target = target;
		if (load) {
			out = target;
			vel = 0;
			return;
		}
	}
	target_vel = (target - last_target) / dt;
	last_target = target;
	err = target - out;
	step_v = err / dt;
	/* close enough to land on the target this period and ride along with it next period */
	if (fabs(step_v - vel) <= a * dt && fabs(step_v - target_vel) <= a * dt
	    && fabs(step_v) <= vmax) {
		vel = step_v;
		out = target;
		return;
	}
	/* fastest relative speed from which braking at a, in steps of dt, stops within |err| */
	v_rel = sqrt(a * dt * a * dt / 4 + 2 * a * fabs(err)) - a * dt / 2;
	v_want = target_vel + (err < 0 ? -v_rel : v_rel);
	v_want = clampd(v_want, -vmax, vmax);
	v_new = clampd(v_want, vel - a * dt, vel + a * dt);
	pos = out + v_new * dt;
	if (pos > max_ || pos < min_) {		/* never leave the window, even mid-correction */
		pos = clampd(pos, min_, max_);
		v_new = (pos - out) / dt;
	}
	vel = v_new;
	out = pos;
}
