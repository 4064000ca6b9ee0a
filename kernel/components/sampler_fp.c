/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sampler_fp.c - the floating-point realtime functions of sampler (see sampler.c), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section (exported with uses_fp = 1). */
#include "sampler_fp.h"

static rtapi_s32 next_s32(rtapi_s32 v)
{
	return (rtapi_s32)((rtapi_u32)v + 1u);	/* wraps without signed overflow */
}

/* One sample per call: drop it (counting an overrun) when the FIFO is full, and
 * flag the next stored sample so halsampler can print "overrun" at the gap. */
COMP_FP_LOCAL void sample(void *arg, long period_ns)
{
	struct sampler *s = arg;
	union hal_fifo_value *rec;
	rtapi_u32 used;
	int m;

	if (*s->enable) {
		rec = hal_fifo_rt_write_slot(s->hdr, &s->fifo, s->data);
		if (!rec) {
			*s->overruns = next_s32(*s->overruns);
			s->gap = true;
		} else {
			rec[HAL_FIFO_REC_SAMPLE].s = *s->sample_num;
			rec[HAL_FIFO_REC_FLAGS].u = s->gap ? HAL_FIFO_GAP : 0;
			rec += HAL_FIFO_REC_HDR_WORDS;
			for (m = 0; m < s->num_pins; m++) {
				switch (s->type[m]) {
				case HAL_FIFO_FLOAT:
					rec[m].f = *s->pins[m].f;
					break;
				case HAL_FIFO_BIT:
					rec[m].u = *s->pins[m].b ? 1 : 0;
					break;
				case HAL_FIFO_S32:
					rec[m].s = *s->pins[m].s;
					break;
				case HAL_FIFO_U32:
					rec[m].u = *s->pins[m].u;
					break;
				default:	/* s64, u64: one untorn load */
					rec[m].u = rtapi_load_u64((volatile rtapi_u64 *)s->pins[m].k);
					break;
				}
			}
			hal_fifo_rt_write_done(s->hdr, &s->fifo);
			s->gap = false;
		}
		*s->sample_num = next_s32(*s->sample_num);
	}
	used = hal_fifo_rt_used(s->hdr, &s->fifo, 1);
	*s->curr_depth = (hal_s32_t)used;
	*s->full = used >= s->fifo.slots - 1;
}
