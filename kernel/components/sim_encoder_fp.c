/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sim_encoder_fp.c - the floating-point realtime functions of sim_encoder (see sim_encoder.c), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section (exported with uses_fp = 1). */
#include "sim_encoder_fp.h"

COMP_FP_LOCAL void sim_encoder_update_speed(void *arg, long period_ns)
{
	struct sim_encoder_set *set = arg;
	int i;

	for (i = 0; i < set->num; i++) {
		struct sim_encoder_chan *c = &set->chan[i];

		sim_enc_update_speed(&c->shared, *c->speed, c->scale, c->ppr, period_ns);
	}
}
