/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_stepgen_fp.c - stepgen motion arithmetic (FP): the 16.16 accumulator becomes
 * counts and position-fb; position-cmd or velocity-cmd becomes the signed rate
 * register (steps/s x 2^32 / clock), within maxvel and maxaccel. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "hal.h"
#include "hm2.h"

void hm2_stepgen_init_fp(struct hostmot2 *hm2)
{
	int i;

	for (i = 0; i < hm2->stepgen.num; i++) {
		struct hm2_stepgen_inst *x = &hm2->stepgen.inst[i];

		x->position_scale = 1.0;
		x->maxvel = 0.0;
		x->maxaccel = 1.0;
		x->old_position_cmd = 0.0;
		x->vel = 0.0;
	}
}

static double scale_of(const struct hm2_stepgen_inst *x)
{
	return x->position_scale != 0.0 ? x->position_scale : 1.0;
}

void hm2_stepgen_read_fp(struct hostmot2 *hm2, long period)
{
	struct hm2_stepgen *s = &hm2->stepgen;
	int i;

	for (i = 0; i < s->num; i++) {
		struct hm2_stepgen_inst *x = &s->inst[i];
		rtapi_u32 acc = s->acc_rd[i];
		rtapi_s64 pos;

		x->subcounts += (rtapi_s32)(acc - x->prev_acc);
		x->prev_acc = acc;
		if (*x->position_reset)
			x->zero = x->subcounts;
		pos = x->subcounts - x->zero;
		*x->counts = (rtapi_s32)(pos >> 16);
		*x->position_fb = (double)pos / 65536.0 / scale_of(x);
	}
}

/* The fastest the step timing allows, in position units per second. */
static double timing_maxvel(const struct hm2_stepgen_inst *x)
{
	double ns = (double)x->steplen + (double)x->stepspace;

	if (ns < 1.0)
		ns = 1.0;
	return 1e9 / ns / rtapi_fabs(scale_of(x));
}

static double limit(double v, double lo, double hi)
{
	return v < lo ? lo : (v > hi ? hi : v);
}

void hm2_stepgen_prepare_write_fp(struct hostmot2 *hm2, long period)
{
	struct hm2_stepgen *s = &hm2->stepgen;
	double dt = (double)period * 1e-9;
	int i;

	for (i = 0; i < s->num; i++) {
		struct hm2_stepgen_inst *x = &s->inst[i];
		double vmax = timing_maxvel(x), v, rate;

		if (x->maxvel > 0.0 && x->maxvel < vmax)
			vmax = x->maxvel;
		if (!*x->enable) {
			x->vel = 0.0;
			x->old_position_cmd = *x->position_cmd;
			*x->velocity_fb = 0.0;
			s->rate_wr[i] = 0;
			continue;
		}
		if (*x->control_type) {
			v = *x->velocity_cmd;
		} else {
			/* feed-forward of the command plus the error closed in one period, no
			 * faster than maxaccel can stop within the remaining distance */
			double ff = (*x->position_cmd - x->old_position_cmd) / dt;
			double err = *x->position_cmd - *x->position_fb;
			double corr = err / dt;

			x->old_position_cmd = *x->position_cmd;
			if (x->maxaccel > 0.0) {
				/* fastest speed that still stops in |err| when slowing by
				 * maxaccel x dt each period: v^2/2a + v dt/2 = |err| */
				double h = x->maxaccel * dt / 2.0;
				double stop = rtapi_sqrt(h * h + 2.0 * x->maxaccel * rtapi_fabs(err)) - h;

				corr = limit(corr, -stop, stop);
			}
			v = ff + corr;
		}
		v = limit(v, -vmax, vmax);
		if (x->maxaccel > 0.0)
			v = limit(v, x->vel - x->maxaccel * dt, x->vel + x->maxaccel * dt);
		x->vel = v;
		*x->velocity_fb = v;
		rate = v * scale_of(x) * 4294967296.0 / (double)s->md->clock_freq;
		rate = limit(rate, -2147483647.0, 2147483647.0);
		s->rate_wr[i] = (rtapi_u32)(rtapi_s32)rate;
	}
}
