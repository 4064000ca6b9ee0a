/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pwmgen_core.h - pwmgen(9) / PWMgen section of the realtime components chapter,
 * HAL-free so unit tests drive it directly. pwmgen_plan_update() (FP, the update
 * function) turns value/scale/offset and the limits into a plan in make-pulses
 * periods; pwmgen_pulse_step() (integer, make-pulses) plays it. Times are 16.16
 * fixed point so that dithering carries the fractions from cycle to cycle;
 * without dither the plan holds whole periods and repeats exactly. */
#ifndef PWMGEN_CORE_H
#define PWMGEN_CORE_H

#include "rtapi.h"

#define PWMGEN_MAX_CHAN 8
#define PWMGEN_FP_ONE 65536u		/* 16.16: one make-pulses period */
#define PWMGEN_MAX_TICKS 65535u		/* longest PWM period, in make-pulses periods */
#define PWMGEN_PDM_ONE (1u << 24)	/* PDM: full duty */

/* Written by update, read by make-pulses. */
struct pwmgen_plan {
	rtapi_u32 period_fp;	/* PWM period, 16.16 periods; 0 = PDM */
	rtapi_u32 high_fp;	/* PWM: high time, 16.16 periods; PDM: duty * PWMGEN_PDM_ONE */
	bool enabled;		/* false: every output low */
	bool reverse;		/* negative duty cycle */
};

/* Parameters update reads (and may correct, as the page says). */
struct pwmgen_settings {
	double scale, offset;
	double pwm_freq;	/* Hz; 0 = PDM; rounded/limited in place */
	double min_dc, max_dc;	/* limited to 0..1 in place */
	bool dither;
	int output_type;	/* 0 PWM only (negative = 0), 1 PWM/dir, 2 up/down */
};

/* Compute the plan for one generator; returns curr-dc (-1..1) after limits and
 * rounding. base_ns is the make-pulses period (0: not known yet, outputs off). */
static inline double pwmgen_plan_update(struct pwmgen_plan *plan, struct pwmgen_settings *s,
					double value, bool enable, rtapi_u32 base_ns)
{
	double dc, mag, fmax, ticks;
	rtapi_u32 n, high;

	if (!(s->max_dc <= 1.0))
		s->max_dc = 1.0;
	if (!(s->max_dc >= 0.0))
		s->max_dc = 0.0;
	if (!(s->min_dc >= 0.0))
		s->min_dc = 0.0;
	if (s->min_dc > s->max_dc)
		s->min_dc = s->max_dc;
	if (!(s->pwm_freq >= 0.0))
		s->pwm_freq = 0.0;
	if (!enable || base_ns == 0) {
		plan->enabled = false;
		return 0.0;	/* "duty cycle will go to zero when disabled" */
	}
	dc = s->scale != 0.0 ? value / s->scale + s->offset : s->offset;
	if (dc != dc)
		dc = 0.0;
	if (s->output_type == 0 && dc < 0.0)
		dc = 0.0;	/* type 0: negative commands count as zero */
	mag = dc < 0.0 ? -dc : dc;
	if (mag > s->max_dc)
		mag = s->max_dc;
	if (mag < s->min_dc)
		mag = s->min_dc;

	if (s->pwm_freq == 0.0) {	/* PDM: inherently dithered, no rounding */
		plan->period_fp = 0;
		plan->high_fp = (rtapi_u32)(mag * PWMGEN_PDM_ONE + 0.5);
	} else {
		fmax = 0.5e9 / base_ns;		/* one period high, one low */
		if (s->pwm_freq > fmax)
			s->pwm_freq = fmax;
		ticks = 1e9 / (s->pwm_freq * base_ns);
		if (ticks > PWMGEN_MAX_TICKS) {	/* below the lowest frequency we can time */
			ticks = PWMGEN_MAX_TICKS;
			s->pwm_freq = 1e9 / (ticks * base_ns);
		}
		if (!s->dither) {	/* whole periods: frequency and duty exactly achievable */
			n = (rtapi_u32)(ticks + 0.5);
			s->pwm_freq = 1e9 / ((double)n * base_ns);
			high = (rtapi_u32)(mag * n + 0.5);
			mag = (double)high / n;
			plan->period_fp = n * PWMGEN_FP_ONE;
			plan->high_fp = high * PWMGEN_FP_ONE;
		} else {
			if (ticks < 2.0)
				ticks = 2.0;
			plan->period_fp = (rtapi_u32)(ticks * PWMGEN_FP_ONE + 0.5);
			plan->high_fp = (rtapi_u32)(mag * ticks * PWMGEN_FP_ONE + 0.5);
		}
	}
	plan->reverse = dc < 0.0;
	plan->enabled = true;
	return plan->reverse ? -mag : mag;
}

/* Owned by make-pulses. */
struct pwmgen_pulse {
	rtapi_u32 count;		/* periods into the current PWM cycle */
	rtapi_u32 cycle_len, cycle_high;	/* whole periods of the current cycle */
	rtapi_u32 period_frac, high_frac;	/* carried fractions (dither) */
	rtapi_u32 pdm_acc;
};

/* One make-pulses period: returns the PWM/PDM level (before direction). A new
 * plan takes effect at the start of the next PWM cycle. */
static inline bool pwmgen_pulse_step(struct pwmgen_pulse *p, const struct pwmgen_plan *plan)
{
	rtapi_u32 period_fp = plan->period_fp, high_fp = plan->high_fp, t;
	bool out;

	if (!plan->enabled) {
		p->count = 0;
		return false;
	}
	if (period_fp == 0) {	/* PDM: first-order sigma-delta */
		p->count = 0;
		p->pdm_acc += high_fp > PWMGEN_PDM_ONE ? PWMGEN_PDM_ONE : high_fp;
		out = p->pdm_acc >= PWMGEN_PDM_ONE;
		if (out)
			p->pdm_acc -= PWMGEN_PDM_ONE;
		return out;
	}
	if (p->count == 0) {	/* new cycle: take whole periods, carry the fractions */
		t = p->period_frac + period_fp;
		p->cycle_len = t >> 16;
		p->period_frac = t & 0xffff;
		t = p->high_frac + high_fp;
		p->cycle_high = t >> 16;
		p->high_frac = t & 0xffff;
		if (p->cycle_len == 0)
			p->cycle_len = 1;
		if (p->cycle_high > p->cycle_len)
			p->cycle_high = p->cycle_len;
	}
	out = p->count < p->cycle_high;
	if (++p->count >= p->cycle_len)
		p->count = 0;
	return out;
}

#endif /* PWMGEN_CORE_H */
