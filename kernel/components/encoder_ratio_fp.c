/* SPDX-License-Identifier: GPL-2.0-or-later */
/* encoder_ratio_fp.c - the floating-point realtime functions of encoder_ratio (see encoder_ratio.c), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section (exported with uses_fp = 1). */
#include "encoder_ratio_fp.h"

COMP_FP_LOCAL void encoder_ratio_update(void *arg, long period_ns)
{
	struct encoder_ratio_set *set = arg;
	int i;

	for (i = 0; i < set->num; i++) {
		struct encoder_ratio_chan *c = &set->chan[i];

		*c->error = enc_ratio_error(&c->counts, c->master_ppr, c->slave_ppr, c->master_teeth,
					    c->slave_teeth);
	}
}
