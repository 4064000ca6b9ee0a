/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sim_encoder_core.h - simulated quadrature encoder, sim_encoder(9) and the
 * Simulated Encoder section; HAL-free so unit tests drive it directly.
 * update-speed (FP) turns speed/scale (revolutions per second) into a 32.32
 * fixed-point count increment per make-pulses period, at most one count so the
 * waveform never skips a quadrature state; make-pulses (no FP) adds it and
 * outputs the quadrature state of the count: 00 -> A -> AB -> B -> 00 going up
 * (A leads B for positive speed), and the index Z during the one count per
 * revolution (4 * ppr counts) that is a multiple of it, when A and B are low. */
#ifndef SIM_ENCODER_CORE_H
#define SIM_ENCODER_CORE_H

#include "rtapi.h"

#define SIM_ENC_ONE_COUNT (1LL << 32)	/* one count in the 32.32 accumulator */

struct sim_enc_shared {
	rtapi_u64 addval;	/* s64 increment per period; written by update-speed */
	rtapi_u32 counts_per_rev;	/* 4 * ppr; written by update-speed */
	rtapi_u32 period_ns;	/* make-pulses' period; written by make-pulses */
};

struct sim_enc_state {		/* private to make-pulses */
	rtapi_u64 accum;	/* counts in the high 32 bits (two's complement), fraction low */
	rtapi_u32 rev_pos;	/* count within the revolution, 0..counts_per_rev-1 */
};

struct sim_enc_out {
	bool a, b, z;
};

/* update-speed: speed in user units/s, scale user units per revolution (|scale|
 * < 1e-20 is taken as 1), ppr pulses per revolution (0 is taken as 1), and the
 * period in ns of the thread that runs make-pulses (0 if it has not run yet:
 * then period_ns, update-speed's own, is used). Realtime, uses FP. */
static inline void sim_enc_update_speed(struct sim_enc_shared *sh, double speed, double scale,
					rtapi_u32 ppr, long period_ns)
{
	rtapi_u32 pulse_period = __atomic_load_n(&sh->period_ns, __ATOMIC_RELAXED);
	double per_period, fixed;
	rtapi_s64 add;

	if (scale < 1e-20 && scale > -1e-20)
		scale = 1.0;
	if (ppr == 0)
		ppr = 1;
	if (pulse_period == 0)
		pulse_period = period_ns > 0 ? (rtapi_u32)period_ns : 0;
	per_period = speed / scale * 4.0 * ppr * pulse_period * 1e-9;
	if (per_period != per_period)	/* NaN: stand still */
		per_period = 0.0;
	else if (per_period > 1.0)
		per_period = 1.0;
	else if (per_period < -1.0)
		per_period = -1.0;
	fixed = per_period * (double)SIM_ENC_ONE_COUNT;
	add = (rtapi_s64)(fixed < 0.0 ? fixed - 0.5 : fixed + 0.5);
	rtapi_store_u64(&sh->addval, (rtapi_u64)add);
	__atomic_store_n(&sh->counts_per_rev, 4 * ppr, __ATOMIC_RELAXED);
}

/* make-pulses: one period. Realtime, no FP. */
static inline void sim_enc_make_pulses(struct sim_enc_state *s, struct sim_enc_shared *sh,
				       long period_ns, struct sim_enc_out *o)
{
	rtapi_u32 per_rev = __atomic_load_n(&sh->counts_per_rev, __ATOMIC_RELAXED);
	rtapi_u32 old_count = (rtapi_u32)(s->accum >> 32), count;

	__atomic_store_n(&sh->period_ns, (rtapi_u32)(period_ns > 0 ? period_ns : 0),
			 __ATOMIC_RELAXED);
	s->accum += rtapi_load_u64(&sh->addval);
	count = (rtapi_u32)(s->accum >> 32);
	if (per_rev == 0)	/* update-speed has not run: no motion yet */
		per_rev = 4;
	if (s->rev_pos >= per_rev)	/* ppr was lowered */
		s->rev_pos = 0;
	if (count == old_count + 1)
		s->rev_pos = s->rev_pos + 1 == per_rev ? 0 : s->rev_pos + 1;
	else if (count == old_count - 1)
		s->rev_pos = s->rev_pos == 0 ? per_rev - 1 : s->rev_pos - 1;
	o->a = (count & 3) == 1 || (count & 3) == 2;
	o->b = (count & 3) >= 2;
	o->z = s->rev_pos == 0;
}

#endif /* SIM_ENCODER_CORE_H */
