/* SPDX-License-Identifier: GPL-2.0-or-later */
/* encoder_fp.c - the floating-point realtime functions of encoder (see encoder.c), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section (exported with uses_fp = 1). */
#include "encoder_fp.h"

COMP_FP_LOCAL void encoder_capture_position(void *arg, long period_ns)
{
	struct encoder_set *set = arg;
	struct enc_capture_in in;
	struct enc_capture_out o;
	struct enc_shared snap;
	int i;

	for (i = 0; i < set->num; i++) {
		struct encoder_chan *e = &set->chan[i];

		enc_shared_read(&e->shared, &snap);
		in.reset = *e->reset;
		in.index_enable = *e->index_enable;
		in.scale = *e->scale;
		in.min_speed = *e->min_speed;
		enc_capture(&e->cap, &snap, &e->acks, &in, &o);
		if (o.clear_index_enable)
			*e->index_enable = false;
		*e->counts = o.counts;
		*e->counts_latched = o.counts_latched;
		*e->position = o.position;
		*e->position_interpolated = o.position_interpolated;
		*e->position_latched = o.position_latched;
		*e->velocity = o.velocity;
	}
}
