/* SPDX-License-Identifier: GPL-2.0-or-later */
/* steptest.comp - steptest(9): the motion source of Stepconf's axis test: jog at maxvel, or run
 * back and forth around the starting position with a trapezoidal velocity profile. */
component steptest "Used by Stepconf to allow testing of acceleration and velocity values for an axis.";
pin in bit jog_minus "Drive TRUE to jog the axis in its minus direction";
pin in bit jog_plus "Drive TRUE to jog the axis in its positive direction";
pin in bit run "Drive TRUE to run the axis near its current position_fb with a trapezoidal velocity profile";
pin in float maxvel "Maximum velocity";
pin in float maxaccel "Permitted Acceleration";
pin in float amplitude "Approximate amplitude of positions to command during 'run'";
pin in s32 dir "Direction from central point to test: 0 = both, 1 = positive, 2 = negative";
pin out float position_cmd;
pin in float position_fb;
pin out bit running;
pin out float run_target;
pin out float run_start;
pin out float run_low;
pin out float run_high;
pin in s32 pause = 0 "pause time for each end of run in seconds";
param rw float epsilon = .001;
param r float elapsed "Current value of the internal timer";
variable double vel;		/* velocity of position-cmd in the previous period, units/s */
function _;
license "GPL";
;;
static double clampd(double v, double lo, double hi)
{
	return v > hi ? hi : v < lo ? lo : v;
}

/* Move *pos towards target by one period: |velocity| <= vmax, |acceleration| <= amax, braking
 * in time to stop on it. Returns 1 once *pos sits on target at rest. */
static int approach(double *pos, double *v, double target, double vmax, double amax, double dt)
{
	double err = target - *pos, dv = amax * dt, v_stop, v_new;

	if (fabs(err / dt - *v) <= dv && fabs(err / dt) <= dv) {
		*v = 0;		/* one last short step lands on target and stops */
		*pos = target;
		return err == 0;
	}
	/* fastest speed from which braking at amax, in steps of dt, stops within |err| */
	v_stop = sqrt(dv * dv / 4 + 2 * amax * fabs(err)) - dv / 2;
	v_new = clampd(err < 0 ? -v_stop : v_stop, -vmax, vmax);
	*v = clampd(v_new, *v - dv, *v + dv);
	*pos += *v * dt;
	return 0;
}

FUNCTION(_)
{
	double dt = fperiod, vmax = fabs(maxvel), amax = fabs(maxaccel), pos = position_cmd;
	double v = vel;

	if (run && !running) {		/* a new run starts from where the axis is */
		double half = fabs(amplitude);

		run_start = position_fb;
		run_low = dir == 1 ? position_fb : position_fb - half;
		run_high = dir == 2 ? position_fb : position_fb + half;
		run_target = dir == 2 ? run_low : run_high;
		running = 1;
		elapsed = 0;
	}
	if (running) {
		if (!run)		/* run released: go back to the start, then stop */
			run_target = run_start;
		if (approach(&pos, &v, run_target, vmax, amax, dt)
		    && fabs(position_fb - run_target) <= epsilon) {
			if (!run) {
				running = 0;
			} else {
				elapsed = elapsed + dt;
				if (elapsed >= pause - dt * 1e-6) {	/* whole periods count exactly */
					elapsed = 0;
					run_target = run_target == run_high ? run_low : run_high;
				}
			}
		}
	} else {
		double want = 0;

		if (jog_plus && !jog_minus)
			want = vmax;
		else if (jog_minus && !jog_plus)
			want = -vmax;
		v = clampd(want, v - amax * dt, v + amax * dt);
		pos += v * dt;
	}
	vel = v;
	position_cmd = pos;
}
