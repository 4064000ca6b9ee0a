/* SPDX-License-Identifier: GPL-2.0-or-later */
/* freqgen_fp.c - the floating-point realtime functions of freqgen (see freqgen.c), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section (exported with uses_fp = 1). */
#include "freqgen_fp.h"

COMP_FP_LOCAL void update_freq(void *arg, long period_ns)
{
	struct freqgen_comp *c = arg;
	rtapi_u32 base_ns = c->base_period_ns;
	int n;

	for (n = 0; n < c->num_chan; n++) {
		struct freqgen_chan *ch = &c->chan[n];
		struct stepgen_timing *t = &ch->timing;
		double flimit, fmax, f;
		rtapi_s64 addval;

		if (base_ns == 0)
			continue;
		if (ch->type == 0) {	/* the page's units: whole make-pulses periods */
			t->steplen = ch->steplen ? ch->steplen : 1;
			t->stepspace = ch->stepspace;
			t->dirsetup = ch->dirsetup;
			t->dirhold = ch->dirhold;
		}
		flimit = stepgen_max_freq(ch->type, t, base_ns);
		if (!(ch->maxfreq >= 0.0))
			ch->maxfreq = 0.0;
		if (ch->maxfreq > flimit)
			ch->maxfreq = flimit;
		fmax = ch->maxfreq > 0.0 ? ch->maxfreq : flimit;
		if (!(ch->maxaccel >= 0.0))
			ch->maxaccel = 0.0;
		f = stepgen_velocity_loop(&ch->loop, *ch->velocity * ch->velocity_scale, fmax,
					  ch->maxaccel, period_ns * 1e-9);
		addval = stepgen_freq_to_addval(f, base_ns);
		rtapi_store_u64(&ch->pulse.addval, (rtapi_u64)addval);
		ch->frequency = stepgen_addval_to_freq(addval, base_ns);
		ch->loop.vel = ch->frequency;
	}
}

COMP_FP_LOCAL void capture_position(void *arg, long period_ns)
{
	struct freqgen_comp *c = arg;
	int n;

	for (n = 0; n < c->num_chan; n++) {
		struct freqgen_chan *ch = &c->chan[n];
		double scale = ch->position_scale;

		if (!(fabs(scale) > 1e-20))
			ch->position_scale = scale = 1.0;
		*ch->counts = ch->pulse.rawcount;
		*ch->position_fb = stepgen_accum_to_steps(rtapi_load_u64(&ch->pulse.accum)) / scale;
	}
}
