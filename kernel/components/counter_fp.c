/* SPDX-License-Identifier: GPL-2.0-or-later */
/* counter_fp.c - the floating-point realtime functions of counter (see counter.c), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section (exported with uses_fp = 1). */
#include "counter_fp.h"

COMP_FP_LOCAL void counter_capture_position(void *arg, long period_ns)
{
	struct counter_set *set = arg;
	struct enc_capture_in in;
	struct enc_capture_out o;
	struct enc_shared snap;
	double mag;
	int i;

	for (i = 0; i < set->num; i++) {
		struct counter_chan *c = &set->chan[i];

		enc_shared_read(&c->shared, &snap);
		in.reset = *c->reset;
		in.index_enable = *c->index_enable;
		in.scale = c->scale;
		mag = c->scale < 0.0 ? -c->scale : c->scale;
		in.min_speed = mag > 1e-20 ? 1.0 / mag : 1.0;	/* one count per second */
		enc_capture(&c->cap, &snap, &c->acks, &in, &o);
		if (o.clear_index_enable)
			*c->index_enable = false;
		*c->counts = o.counts;
		*c->position = o.position;
		*c->velocity = o.velocity;
		c->index_armed = *c->index_enable;
	}
}
