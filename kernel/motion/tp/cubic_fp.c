/* cubic_fp.c - per-joint cubic (Hermite) interpolation between trajectory points
 * (motion.md §3).  See cubic.h.  FP unit. */
#include "cubic.h"
#include "rtapi_math.h"

int cubic_init(struct cubic *cb, double traj_period, double servo_period)
{
	if (!cb || !(servo_period > 0) || !(traj_period >= servo_period) || traj_period > 1.0)
		return -1;
	int rate = (int)rtapi_round(traj_period / servo_period);
	if (rate < 1)
		rate = 1;
	cb->rate = rate;
	cb->interp_time = servo_period;
	cb->segment_time = servo_period * rate;
	cubic_drain(cb);
	return 0;
}

void cubic_drain(struct cubic *cb)
{
	cb->filled = 0;
	cb->need_point = 1;
	cb->step = 0;
}

void cubic_offset(struct cubic *cb, double delta)
{
	cb->x0 += delta;
	cb->x1 += delta;
	cb->x2 += delta;
	cb->x3 += delta;
	cb->wp0 += delta;
	cb->wp1 += delta;
	cb->d += delta;
}

int cubic_needs_next_point(const struct cubic *cb)
{
	return cb->need_point;
}

void cubic_add_point(struct cubic *cb, double point)
{
	double t = cb->segment_time;
	if (!cb->filled) {
		cb->x0 = cb->x1 = cb->x2 = cb->x3 = point;
		cb->filled = 1;
	} else {
		cb->x0 = cb->x1;
		cb->x1 = cb->x2;
		cb->x2 = cb->x3;
		cb->x3 = point;
	}
	/* way-points and slopes at x1 and x2, joined over one trajectory period */
	cb->wp0 = (cb->x0 + 4 * cb->x1 + cb->x2) / 6;
	cb->wp1 = (cb->x1 + 4 * cb->x2 + cb->x3) / 6;
	cb->v0 = (cb->x2 - cb->x0) / (2 * t);
	cb->v1 = (cb->x3 - cb->x1) / (2 * t);
	double dp = cb->wp1 - cb->wp0;
	cb->d = cb->wp0;
	cb->c = cb->v0;
	cb->b = (3 * dp / t - 2 * cb->v0 - cb->v1) / t;
	cb->a = (cb->v0 + cb->v1 - 2 * dp / t) / (t * t);
	cb->step = 0;
	cb->need_point = 0;
}

double cubic_interpolate(struct cubic *cb, double *vel, double *acc)
{
	double t = (cb->step + 1) * cb->interp_time;
	double pos = ((cb->a * t + cb->b) * t + cb->c) * t + cb->d;
	if (vel)
		*vel = (3 * cb->a * t + 2 * cb->b) * t + cb->c;
	if (acc)
		*acc = 6 * cb->a * t + 2 * cb->b;
	if (++cb->step >= cb->rate)
		cb->need_point = 1;
	return pos;
}
