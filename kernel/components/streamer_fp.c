/* SPDX-License-Identifier: GPL-2.0-or-later */
/* streamer_fp.c - the floating-point realtime functions of streamer (see streamer.c), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section (exported with uses_fp = 1). */
#include "streamer_fp.h"

/* Does clock-mode ask for a record in this period? */
static bool clocked(struct streamer *s)
{
	bool clk = *s->clock, last = s->last_clock;

	s->last_clock = clk;
	switch (*s->clock_mode) {
	case STREAMER_CLOCK_FALLING: return last && !clk;
	case STREAMER_CLOCK_RISING: return !last && clk;
	case STREAMER_CLOCK_BOTH: return last != clk;
	default: return true;
	}
}

/* One record per call (per clock edge with clock-mode 1..3); with none available the
 * pins keep their values and an underrun is counted. */
COMP_FP_LOCAL void update(void *arg, long period_ns)
{
	struct streamer *s = arg;
	const union hal_fifo_value *rec;
	rtapi_u32 used;
	int m;

	if (clocked(s) && *s->enable) {
		rec = hal_fifo_rt_read_slot(s->hdr, &s->fifo, s->data);
		if (!rec) {
			*s->underruns = (hal_s32_t)((rtapi_u32)*s->underruns + 1u);
		} else {
			rec += HAL_FIFO_REC_HDR_WORDS;
			for (m = 0; m < s->num_pins; m++) {
				switch (s->type[m]) {
				case HAL_FIFO_FLOAT:
					*s->pins[m].f = rec[m].f;
					break;
				case HAL_FIFO_BIT:
					*s->pins[m].b = rec[m].u != 0;
					break;
				case HAL_FIFO_S32:
					*s->pins[m].s = (hal_s32_t)rec[m].s;
					break;
				case HAL_FIFO_U32:
					*s->pins[m].u = (rtapi_u32)rec[m].u;
					break;
				default:	/* s64, u64: one untorn store */
					rtapi_store_u64((volatile rtapi_u64 *)s->pins[m].k, rec[m].u);
					break;
				}
			}
			hal_fifo_rt_read_done(s->hdr, &s->fifo);
		}
	}
	used = hal_fifo_rt_used(s->hdr, &s->fifo, 0);
	*s->curr_depth = (hal_s32_t)used;
	*s->empty = used == 0;
}
