/* SPDX-License-Identifier: GPL-2.0-or-later */
/* stepgen_loop.h - the FP half of stepgen(9) (update-freq): the step-rate limit
 * from the timing, the acceleration-limited position loop and the velocity
 * ramp, and the conversion of a velocity into the per-period addval that
 * make-pulses integrates. HAL-free so unit tests drive it directly; call only
 * from functions exported with uses_fp = 1. */
#ifndef STEPGEN_LOOP_H
#define STEPGEN_LOOP_H

#include "rtapi.h"
#include "rtapi_math.h"
#include "stepgen_core.h"

/* Owned by update-freq. */
struct stepgen_loop {
	double vel;		/* velocity being output, position units/s */
	double old_cmd;		/* position command at the previous call */
	double old_cmd_vel;	/* velocity of the command seen at the previous call */
	bool has_old;		/* old_cmd is valid (false after start and while disabled) */
};

static inline double stepgen_clamp(double v, double lo, double hi)
{
	return v < lo ? lo : (v > hi ? hi : v);
}

/* Highest step rate, steps/s, the rounded timing allows at this base period. */
static inline double stepgen_max_freq(int type, const struct stepgen_timing *t,
				      rtapi_u32 base_ns)
{
	if (base_ns == 0)
		return 0.0;
	return 1e9 / ((double)stepgen_periods_per_step(type, t) * (double)base_ns);
}

/* Fastest speed toward a target dist (>= 0) away that still allows stopping
 * without passing it, when the speed is held for one period t and then lowered
 * by a*t each period: v*t + v^2/(2a) = dist, solved in a form that does not
 * cancel for small distances. */
static inline double stepgen_stop_vel(double dist, double a, double t)
{
	double at = a * t;

	if (dist <= 0.0)
		return 0.0;
	return 2.0 * a * dist / (at + sqrt(at * at + 2.0 * a * dist));
}

/* Position mode: the velocity for the next period t (s) that moves pos toward
 * cmd, never faster than vmax, never changing by more than amax*t per period
 * (amax 0 = no limit), and never passing a command that stands still. A command
 * that moves within the limits is followed without lag (its velocity is fed
 * forward); one that jumps is treated as a new stationary target. */
static inline double stepgen_position_loop(struct stepgen_loop *l, double cmd, double pos,
					   double vmax, double amax, double t)
{
	double err = cmd - pos;
	double w = 0.0, w_raw, at = amax * t, u, v;

	if (err != err)		/* NaN command: hold still */
		err = 0.0;
	if (l->has_old && t > 0.0) {
		w_raw = (cmd - l->old_cmd) / t;
		if (amax > 0.0 && fabs(w_raw - l->old_cmd_vel) <= 1.5 * at && fabs(w_raw) <= vmax)
			w = w_raw;
		l->old_cmd_vel = w_raw;
	} else {
		l->old_cmd_vel = 0.0;
	}
	l->old_cmd = cmd;
	l->has_old = true;
	if (t <= 0.0)
		return 0.0;
	if (amax <= 0.0)
		return stepgen_clamp(err / t, -vmax, vmax);	/* arrive within one period */
	u = l->vel - w;		/* velocity relative to the command */
	v = err >= 0.0 ? stepgen_stop_vel(err, amax, t) : -stepgen_stop_vel(-err, amax, t);
	v = w + stepgen_clamp(v, u - at, u + at);
	v = stepgen_clamp(v, l->vel - at, l->vel + at);
	return stepgen_clamp(v, -vmax, vmax);
}

/* Velocity mode: vcmd limited to +-vmax, reached at amax (0 = at once). */
static inline double stepgen_velocity_loop(const struct stepgen_loop *l, double vcmd,
					   double vmax, double amax, double t)
{
	double v = vcmd != vcmd ? 0.0 : stepgen_clamp(vcmd, -vmax, vmax);

	if (amax > 0.0)
		v = stepgen_clamp(v, l->vel - amax * t, l->vel + amax * t);
	return v;
}

/* Steps/s to the per-period accumulator increment, truncated toward zero so the
 * generator never runs ahead of the plan. */
static inline rtapi_s64 stepgen_freq_to_addval(double freq, rtapi_u32 base_ns)
{
	double a = freq * (double)base_ns * 1e-9 * (double)STEPGEN_ONE_STEP;

	if (!(a < (double)STEPGEN_ONE_STEP))
		return STEPGEN_ONE_STEP;
	if (!(a > -(double)STEPGEN_ONE_STEP))
		return -STEPGEN_ONE_STEP;
	return (rtapi_s64)a;
}

/* The inverse: the step rate an addval really produces. */
static inline double stepgen_addval_to_freq(rtapi_s64 addval, rtapi_u32 base_ns)
{
	if (base_ns == 0)
		return 0.0;
	return (double)addval / (double)STEPGEN_ONE_STEP / ((double)base_ns * 1e-9);
}

/* Accumulator to position in steps (undoing the half-step start offset). */
static inline double stepgen_accum_to_steps(rtapi_u64 accum)
{
	return (double)((rtapi_s64)accum - STEPGEN_HALF_STEP) / (double)STEPGEN_ONE_STEP;
}

#endif /* STEPGEN_LOOP_H */
