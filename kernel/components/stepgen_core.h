/* SPDX-License-Identifier: GPL-2.0-or-later */
/* stepgen_core.h - stepgen(9) / StepGen section of the realtime components
 * chapter: step patterns, timing rounding and the per-period pulse maker,
 * HAL-free so unit tests drive it directly. Integer only (make-pulses is a
 * no-FP function); the FP control loops are in stepgen_loop.h.
 *
 * Position is a fixed-point accumulator: one step is 2^32, and it starts half a
 * step up, so a step is made when the commanded position crosses the middle
 * between two step positions (rounding, the same in both directions). */
#ifndef STEPGEN_CORE_H
#define STEPGEN_CORE_H

#include "rtapi.h"

#define STEPGEN_MAX_CHAN 8	/* "maximum number of step generators is 8" */
#define STEPGEN_NUM_TYPES 16	/* 0-14 built in, 15 from user_step_type= */
#define STEPGEN_USER_TYPE 15
#define STEPGEN_MAX_CYCLE 10	/* states per cycle of a phase pattern */
#define STEPGEN_MAX_PHASES 5	/* phase-A .. phase-E */
#define STEPGEN_ONE_STEP (1LL << 32)
#define STEPGEN_HALF_STEP (1LL << 31)
#define STEPGEN_TIMER_MAX 0x40000000u	/* saturation of the "periods since" counters */

/* Output bits of one state-based pattern: bit 0 drives phase-A ... bit 4 phase-E. */
struct stepgen_pattern {
	rtapi_u8 len;		/* states per cycle */
	rtapi_u8 phases;	/* phase pins used */
	rtapi_u8 bits[STEPGEN_MAX_CYCLE];
};

/* Step types 2-14, as the "Two-and-Three-Phase", "Four-Phase" and "Five-Phase"
 * tables of the StepGen section list them; forward steps walk the states upward. */
static const struct stepgen_pattern stepgen_builtin_patterns[15] = {
	{ 0, 0, { 0 } },					/* 0: step/dir, no table */
	{ 0, 0, { 0 } },					/* 1: up/down, no table */
	{ 4, 2, { 1, 3, 2, 0 } },				/* 2: quadrature: A leads B */
	{ 3, 3, { 1, 2, 4 } },				/* 3: three phase, full step */
	{ 6, 3, { 1, 3, 2, 6, 4, 5 } },			/* 4: three phase, half step */
	{ 4, 4, { 1, 2, 4, 8 } },				/* 5: unipolar full step 1 */
	{ 4, 4, { 3, 6, 12, 9 } },			/* 6: unipolar full step 2 */
	{ 4, 4, { 1, 7, 14, 8 } },			/* 7: bipolar full step 1 */
	{ 4, 4, { 5, 6, 10, 9 } },			/* 8: bipolar full step 2 */
	{ 8, 4, { 1, 3, 2, 6, 4, 12, 8, 9 } },		/* 9: unipolar half step */
	{ 8, 4, { 1, 5, 7, 6, 14, 10, 8, 9 } },		/* 10: bipolar half step */
	{ 5, 5, { 1, 2, 4, 8, 16 } },			/* 11: five phase, full step 1 */
	{ 5, 5, { 3, 6, 12, 24, 17 } },			/* 12: five phase, full step 2 */
	{ 10, 5, { 1, 3, 2, 6, 4, 12, 8, 24, 16, 17 } },	/* 13: five phase, half step 1 */
	{ 10, 5, { 3, 7, 6, 14, 12, 28, 24, 25, 17, 19 } },	/* 14: five phase, half step 2 */
};

/* Build the type 15 pattern from user_step_type= (entries up to the first
 * negative one). Returns 0, -EINVAL when an entry uses bits beyond phase-E
 * (*bad_entry gets its index), or -ENOENT when no entry was given. Init only. */
static inline int stepgen_user_pattern(const int *entries, int n, struct stepgen_pattern *pat,
				       int *bad_entry)
{
	int i, used = 0;

	pat->len = 0;
	pat->phases = 0;
	for (i = 0; i < n && i < STEPGEN_MAX_CYCLE && entries[i] >= 0; i++) {
		if (entries[i] & ~0x1f) {
			*bad_entry = i;
			return -EINVAL;
		}
		pat->bits[i] = (rtapi_u8)entries[i];
		used |= entries[i];
	}
	if (i == 0)
		return -ENOENT;
	pat->len = (rtapi_u8)i;
	while (used) {		/* the highest phase used decides how many pins exist */
		pat->phases++;
		used >>= 1;
	}
	if (pat->phases == 0)
		pat->phases = 1;	/* all-zero pattern: still one (always low) pin */
	return 0;
}

/* Timing in make-pulses periods (the ns parameters rounded up). */
struct stepgen_timing {
	rtapi_u32 steplen;	/* >= 1: periods a step pin is high / a state is held */
	rtapi_u32 stepspace;	/* periods low between pulses; 0 = doublefreq */
	rtapi_u32 dirsetup;	/* periods from a dir change to the next rising step */
	rtapi_u32 dirhold;	/* periods from a falling step to a dir change */
	rtapi_u32 dirdelay;	/* extra periods before a step in the other direction */
};

/* ns rounded UP to whole periods, as "rounded up to an integer multiple of the
 * thread period" requires; capped so sums of two never overflow. */
static inline rtapi_u32 stepgen_ns_to_periods(rtapi_u32 ns, rtapi_u32 period_ns)
{
	rtapi_u32 n;

	if (ns == 0 || period_ns == 0)
		return 0;
	n = (ns - 1) / period_ns + 1;
	return n > STEPGEN_TIMER_MAX ? STEPGEN_TIMER_MAX : n;
}

/* Periods one step takes at the highest rate: steplen + stepspace for types 0
 * and 1 (one period when both round to less), steplen for the state types. */
static inline rtapi_u32 stepgen_periods_per_step(int type, const struct stepgen_timing *t)
{
	rtapi_u32 n = t->steplen;

	if (type <= 1)
		n += t->stepspace;
	return n ? n : 1;
}

/* State of one generator's pulse maker, owned by make-pulses (accum, rawcount,
 * outputs) except addval, which update-freq writes. */
struct stepgen_pulse {
	rtapi_u64 accum;	/* s64 position, 2^32 per step, through rtapi_load/store_u64 */
	rtapi_u64 addval;	/* s64 added per period: written by update-freq only */
	rtapi_s32 rawcount;	/* steps made */
	rtapi_u32 since_step;	/* periods since the last step (rising edge / state change) */
	rtapi_u32 since_fall;	/* types 0, 1: periods since the step pin fell */
	rtapi_u32 since_dir;	/* type 0: periods since dir changed */
	rtapi_s8 last_dir;	/* +1 / -1: direction of the last step */
	rtapi_u8 state;		/* types 2+: index into the pattern */
	bool pulse_high;	/* types 0, 1: a step pulse is being output */
	bool dir_pin;		/* type 0: direction output, true = reverse */
	bool hold;		/* a step is due but timing forbids it: stop integrating */
	bool out[STEPGEN_MAX_PHASES];	/* output levels, see stepgen_pulse_step() */
};

static inline void stepgen_pulse_init(struct stepgen_pulse *p)
{
	int i;

	p->accum = (rtapi_u64)STEPGEN_HALF_STEP;
	p->addval = 0;
	p->rawcount = 0;
	p->since_step = p->since_fall = p->since_dir = STEPGEN_TIMER_MAX;
	p->last_dir = 1;
	p->state = 0;
	p->pulse_high = p->dir_pin = p->hold = false;
	for (i = 0; i < STEPGEN_MAX_PHASES; i++)
		p->out[i] = false;
}

static inline void stepgen_count(rtapi_u32 *c)
{
	if (*c < STEPGEN_TIMER_MAX)
		(*c)++;
}

/* May a step in direction dir (+1/-1) start this period? Type 0 also turns the
 * dir pin around here once dirhold allows it (dirsetup then delays the step). */
static inline bool stepgen_may_step(struct stepgen_pulse *p, int type,
				    const struct stepgen_timing *t, int dir)
{
	bool reverse = dir != p->last_dir;

	if (type == 0) {
		if (p->dir_pin != (dir < 0)) {
			if (p->pulse_high || p->since_fall < t->dirhold)
				return false;
			p->dir_pin = dir < 0;
			p->since_dir = 0;
		}
		return !p->pulse_high && p->since_fall >= t->stepspace &&
		       p->since_dir >= t->dirsetup;
	}
	if (type == 1)
		return !p->pulse_high && p->since_fall >= t->stepspace &&
		       (!reverse || p->since_fall >= t->dirdelay);
	return p->since_step >= t->steplen &&
	       (!reverse || p->since_step >= t->steplen + t->dirdelay);
}

/* Type 0, no step due: the dir pin follows the sign of the rate as soon as dirhold
 * allows, as LinuxCNC's stepgen does, so that dirsetup has passed by the time the
 * accumulator crosses and the first step the other way comes in that very period. */
static inline void stepgen_turn_early(struct stepgen_pulse *p, const struct stepgen_timing *t,
				      rtapi_s64 addval)
{
	bool reverse = addval < 0;

	if (addval == 0 || p->dir_pin == reverse || p->pulse_high || p->since_fall < t->dirhold)
		return;
	p->dir_pin = reverse;
	p->since_dir = 0;
}

/* One make-pulses period for one generator: time passes, the position advances
 * by addval (unless held or disabled), at most one step is made, and out[] is
 * set: type 0 out[0] = step, out[1] = dir; type 1 out[0] = up, out[1] = down;
 * types 2-15 out[0..4] = phase-A..E from pat. Returns the step made: -1, 0, +1. */
static inline int stepgen_pulse_step(struct stepgen_pulse *p, int type,
				     const struct stepgen_pattern *pat,
				     const struct stepgen_timing *t, bool enable)
{
	rtapi_s64 accum = (rtapi_s64)rtapi_load_u64(&p->accum);
	rtapi_s64 target;
	int dir = 0, i, bits;

	stepgen_count(&p->since_step);
	stepgen_count(&p->since_dir);
	if (p->pulse_high && p->since_step >= t->steplen) {
		p->pulse_high = false;
		p->since_fall = 0;
	} else if (!p->pulse_high) {
		stepgen_count(&p->since_fall);
	}

	if (enable) {
		if (!p->hold) {
			accum += (rtapi_s64)rtapi_load_u64(&p->addval);
			rtapi_store_u64(&p->accum, (rtapi_u64)accum);
		}
		target = accum >> 32;	/* floor: gcc shifts signed values arithmetically */
		if (type == 0 && target == p->rawcount)
			stepgen_turn_early(p, t, (rtapi_s64)rtapi_load_u64(&p->addval));
		if (target != p->rawcount) {
			dir = target > p->rawcount ? 1 : -1;
			if (stepgen_may_step(p, type, t, dir)) {
				p->rawcount += dir;
				p->last_dir = (rtapi_s8)dir;
				p->since_step = 0;
				if (type <= 1)
					p->pulse_high = true;
				else if (dir > 0)
					p->state = p->state + 1 >= pat->len ? 0 : p->state + 1;
				else
					p->state = p->state == 0 ? pat->len - 1 : p->state - 1;
			} else {
				dir = 0;
			}
		}
		p->hold = target != p->rawcount;
	}

	if (type == 0) {
		p->out[0] = p->pulse_high;
		p->out[1] = p->dir_pin;
	} else if (type == 1) {
		p->out[0] = p->pulse_high && p->last_dir > 0;
		p->out[1] = p->pulse_high && p->last_dir < 0;
	} else {
		bits = pat->len ? pat->bits[p->state] : 0;
		for (i = 0; i < STEPGEN_MAX_PHASES; i++)
			p->out[i] = (bits >> i) & 1;
	}
	return dir;
}

#endif /* STEPGEN_CORE_H */
