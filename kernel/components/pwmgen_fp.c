/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pwmgen_fp.c - the floating-point realtime functions of pwmgen (see pwmgen.c), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section (exported with uses_fp = 1). */
#include "pwmgen_fp.h"

COMP_FP_LOCAL void update(void *arg, long period_ns)
{
	struct pwmgen_comp *c = arg;
	int n;

	for (n = 0; n < c->num_chan; n++) {
		struct pwmgen_chan *ch = &c->chan[n];
		struct pwmgen_settings s = {
			.scale = ch->scale, .offset = ch->offset, .pwm_freq = ch->pwm_freq,
			.min_dc = ch->min_dc, .max_dc = ch->max_dc, .dither = ch->dither,
			.output_type = ch->type,
		};
		struct pwmgen_plan plan = ch->plan;

		ch->curr_dc = pwmgen_plan_update(&plan, &s, *ch->value, *ch->enable,
						 c->base_period_ns);
		ch->plan = plan;
		/* write back only what the page says update corrects */
		if (s.pwm_freq != ch->pwm_freq)
			ch->pwm_freq = s.pwm_freq;
		if (s.min_dc != ch->min_dc)
			ch->min_dc = s.min_dc;
		if (s.max_dc != ch->max_dc)
			ch->max_dc = s.max_dc;
	}
}
