/* SPDX-License-Identifier: GPL-2.0-or-later */
/* stepgen_fp.c - the floating-point realtime functions of stepgen (see stepgen.c), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section (exported with uses_fp = 1). */
#include "stepgen_fp.h"

/* Position-scale 0 (or NaN) would divide by zero: use 1.0, as the default. */
static double usable_scale(struct stepgen_chan *ch)
{
	double s = ch->position_scale;

	if (!(fabs(s) > 1e-20)) {
		ch->position_scale = 1.0;
		s = 1.0;
	}
	return s;
}

static void update_timing(struct stepgen_chan *ch, rtapi_u32 base_ns)
{
	struct stepgen_timing *t = &ch->timing;

	t->steplen = stepgen_ns_to_periods(ch->steplen, base_ns);
	if (t->steplen == 0)
		t->steplen = 1;		/* a step pin must be high for at least one period */
	t->stepspace = stepgen_ns_to_periods(ch->stepspace, base_ns);
	t->dirsetup = stepgen_ns_to_periods(ch->dirsetup, base_ns);
	t->dirhold = stepgen_ns_to_periods(ch->dirhold, base_ns);
	t->dirdelay = stepgen_ns_to_periods(ch->dirdelay, base_ns);
}

COMP_FP_LOCAL void update_freq(void *arg, long period_ns)
{
	struct stepgen_comp *c = arg;
	rtapi_u32 base_ns = c->base_period_ns;
	double t = period_ns * 1e-9;
	int n;

	for (n = 0; n < c->num_chan; n++) {
		struct stepgen_chan *ch = &c->chan[n];
		double scale = usable_scale(ch);
		double vlimit, vmax, amax, pos, v;
		rtapi_s64 addval;

		if (base_ns == 0 || !*ch->enable) {	/* make-pulses has not run yet, or off */
			rtapi_store_u64(&ch->pulse.addval, 0);
			ch->loop.vel = 0.0;
			ch->loop.has_old = false;
			ch->frequency = 0.0;
			continue;
		}
		update_timing(ch, base_ns);
		vlimit = stepgen_max_freq(ch->type, &ch->timing, base_ns) / fabs(scale);
		if (!(ch->maxvel >= 0.0))
			ch->maxvel = 0.0;
		if (ch->maxvel > vlimit)
			ch->maxvel = vlimit;	/* "reset to the highest attainable value" */
		vmax = ch->maxvel > 0.0 ? ch->maxvel : vlimit;
		if (!(ch->maxaccel >= 0.0))
			ch->maxaccel = 0.0;
		amax = ch->maxaccel;
		if (ch->velocity_mode) {
			v = stepgen_velocity_loop(&ch->loop, *ch->cmd, vmax, amax, t);
		} else {
			pos = stepgen_accum_to_steps(rtapi_load_u64(&ch->pulse.accum)) / scale;
			v = stepgen_position_loop(&ch->loop, *ch->cmd, pos, vmax, amax, t);
		}
		addval = stepgen_freq_to_addval(v * scale, base_ns);
		rtapi_store_u64(&ch->pulse.addval, (rtapi_u64)addval);
		ch->frequency = stepgen_addval_to_freq(addval, base_ns);
		ch->loop.vel = ch->frequency / scale;	/* what is really output */
	}
}

COMP_FP_LOCAL void capture_position(void *arg, long period_ns)
{
	struct stepgen_comp *c = arg;
	int n;

	for (n = 0; n < c->num_chan; n++) {
		struct stepgen_chan *ch = &c->chan[n];

		*ch->counts = ch->pulse.rawcount;
		*ch->position_fb = stepgen_accum_to_steps(rtapi_load_u64(&ch->pulse.accum)) /
				   usable_scale(ch);
	}
}
