/* SPDX-License-Identifier: GPL-2.0-or-later */
/* encoder_ratio_core.h - the electronic gear of encoder_ratio(9), HAL-free so unit
 * tests drive it. sample (fast, no FP) counts both quadrature inputs (x4, as
 * encoder(9) does: encoder_core.h); the master only while enable is TRUE, and
 * its count restarts from 0 each time enable goes TRUE. update (FP) reports
 *   error = slave revolutions - master revolutions * master-teeth / slave-teeth
 * with revolutions = counts / (4 * ppr); while enable is FALSE the master term
 * is 0, so error is the slave position. A ppr of 0 is taken as 1; a slave-teeth
 * of 0 drops the master term (no ratio can be formed). */
#ifndef ENCODER_RATIO_CORE_H
#define ENCODER_RATIO_CORE_H

#include "rtapi.h"
#include "encoder_core.h"

struct enc_ratio_counts {	/* written by sample only, read by update */
	rtapi_u64 master, slave;	/* s64 counts, as u64 so they move untorn */
};

struct enc_ratio_state {	/* private to sample */
	bool primed;		/* false until the first sample */
	rtapi_u8 master_pos, slave_pos;	/* quadrature positions of the last sample */
	rtapi_s64 master, slave;
};

/* One sample. Realtime, no FP. */
static inline void enc_ratio_sample(struct enc_ratio_state *s, struct enc_ratio_counts *out,
				    bool master_a, bool master_b, bool slave_a, bool slave_b,
				    bool enable)
{
	rtapi_u8 mpos = enc_quad_pos(master_a, master_b);
	rtapi_u8 spos = enc_quad_pos(slave_a, slave_b);

	if (!s->primed) {
		s->primed = true;
		s->master_pos = mpos;
		s->slave_pos = spos;
	}
	if (enable)
		s->master += enc_quad_delta(s->master_pos, mpos, true);
	else
		s->master = 0;
	s->slave += enc_quad_delta(s->slave_pos, spos, true);
	s->master_pos = mpos;
	s->slave_pos = spos;
	rtapi_store_u64(&out->master, (rtapi_u64)s->master);
	rtapi_store_u64(&out->slave, (rtapi_u64)s->slave);
}

/* The error pin. Realtime, uses FP. */
static inline double enc_ratio_error(const struct enc_ratio_counts *c, rtapi_u32 master_ppr,
				     rtapi_u32 slave_ppr, rtapi_u32 master_teeth,
				     rtapi_u32 slave_teeth)
{
	double slave = (double)(rtapi_s64)rtapi_load_u64(&c->slave) /
		       (4.0 * (slave_ppr ? slave_ppr : 1));
	double master = (double)(rtapi_s64)rtapi_load_u64(&c->master) /
			(4.0 * (master_ppr ? master_ppr : 1));

	if (slave_teeth == 0)
		return slave;
	return slave - master * master_teeth / slave_teeth;
}

#endif /* ENCODER_RATIO_CORE_H */
