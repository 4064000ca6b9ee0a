/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_encoder_fp.c - encoder arithmetic, run inside read() (FP thread) or between
 * rtapi_fpu_begin/end: 16-bit counts extended to 64 bits, index/probe latch events,
 * position, and timestamp-based velocity (hostmot2.md 7.4). */
#include "rtapi.h"
#include "rtapi_math.h"
#include "hal.h"
#include "hm2.h"

#define CTL_QUAD_ERROR (1u << 15)
#define CTL_LATCH_PROBE (1u << 13)
#define CTL_LATCH_INDEX (1u << 4)

void hm2_encoder_init_fp(struct hostmot2 *hm2)
{
	int i;

	for (i = 0; i < hm2->encoder.num; i++) {
		hm2->encoder.inst[i].scale = 1.0;
		hm2->encoder.inst[i].vel_timeout = 0.5;
	}
}

/* After the load-time read: the count starts at 0. */
void hm2_encoder_prepare_fp(struct hostmot2 *hm2)
{
	struct hm2_encoder *e = &hm2->encoder;
	int i;

	for (i = 0; i < e->num; i++) {
		struct hm2_encoder_inst *x = &e->inst[i];

		x->prev16 = e->counter_rd[i] & 0xFFFF;
		x->raw = 0;
		x->zero = 0;
		x->time_since_event_ns = 0x7FFFFFFF;
	}
}

static double scaled(const struct hm2_encoder_inst *x, rtapi_s64 counts)
{
	double s = x->scale != 0.0 ? x->scale : 1.0;

	return (double)counts / s;
}

/* the latched 16-bit count, extended against the current raw count */
static rtapi_s64 extend(rtapi_s64 raw, rtapi_u32 control)
{
	rtapi_u16 latched = control >> 16;

	return raw + (rtapi_s16)(latched - (rtapi_u16)raw);
}

static void velocity(struct hm2_encoder *e, struct hm2_encoder_inst *x, int delta,
		     rtapi_u16 ts, rtapi_u16 tscount, long period)
{
	double tick_s = (double)(e->tsdiv + 2) / (double)e->md->clock_freq;
	double wrap_s = 65536.0 * tick_s, since, v;

	if (delta) {
		double dt = (double)period * 1e-9;

		if (x->has_event && (double)x->time_since_event_ns * 1e-9 + dt < wrap_s) {
			rtapi_u16 ticks = ts - x->prev_event_ts;

			if (ticks)
				dt = ticks * tick_s;
		}
		*x->velocity = scaled(x, delta) / dt;
		x->prev_event_ts = ts;
		x->has_event = 1;
		x->time_since_event_ns = (rtapi_s32)((rtapi_u16)(tscount - ts) * tick_s * 1e9);
	} else if (x->time_since_event_ns < 0x7FFFFFFF - period) {
		x->time_since_event_ns += period;
	}
	since = (double)x->time_since_event_ns * 1e-9;
	if (!delta) {
		if (!x->has_event || since > x->vel_timeout) {
			*x->velocity = 0.0;
		} else {
			/* no count yet: the speed is at most one count per elapsed time */
			double bound = rtapi_fabs(scaled(x, 1)) / since;

			if (rtapi_fabs(*x->velocity) > bound)
				*x->velocity = *x->velocity > 0 ? bound : -bound;
		}
	}
	v = *x->velocity;
	*x->velocity_rpm = v * 60.0;
	if (since < x->vel_timeout && v != 0.0) {
		double extra = v * since, one = rtapi_fabs(scaled(x, 1));

		if (extra > one)
			extra = one;
		if (extra < -one)
			extra = -one;
		*x->position_interpolated = *x->position + extra;
	} else {
		*x->position_interpolated = *x->position;
	}
}

void hm2_encoder_read_fp(struct hostmot2 *hm2, long period)
{
	struct hm2_encoder *e = &hm2->encoder;
	rtapi_u16 tscount;
	int i;

	if (!e->num)
		return;
	tscount = *e->tscount_rd & 0xFFFF;
	for (i = 0; i < e->num; i++) {
		struct hm2_encoder_inst *x = &e->inst[i];
		rtapi_u32 cnt = e->counter_rd[i], ctl = e->control_rd[i];
		rtapi_u16 c16 = cnt & 0xFFFF;
		int delta = (rtapi_s16)(c16 - x->prev16);

		x->prev16 = c16;
		x->raw += delta;
		/* the hardware clears the latch bit (JustOnce) when the event happened */
		if ((x->written_control & CTL_LATCH_INDEX) && !(ctl & CTL_LATCH_INDEX) &&
		    *x->index_enable) {
			x->zero = extend(x->raw, ctl);
			*x->index_enable = 0;
		}
		if ((x->written_control & CTL_LATCH_PROBE) && !(ctl & CTL_LATCH_PROBE) &&
		    *x->probe_enable) {
			*x->position_latched = scaled(x, extend(x->raw, ctl) - x->zero);
			*x->probe_enable = 0;
		}
		if (*x->reset)
			x->zero = x->raw;
		*x->rawcounts = (rtapi_s32)x->raw;
		*x->count = (rtapi_s32)(x->raw - x->zero);
		*x->position = scaled(x, x->raw - x->zero);
		velocity(e, x, delta, cnt >> 16, tscount, period);
		*x->input_a = ctl & 1;
		*x->input_b = (ctl >> 1) & 1;
		*x->input_index = (ctl >> 2) & 1;
		*x->quad_error = *x->quad_error_enable && (ctl & CTL_QUAD_ERROR);
	}
}

/* muxed-skew (ns) -> ClockLow periods, 0..15, for the filter-rate register */
void hm2_encoder_write_fp(struct hostmot2 *hm2)
{
	struct hm2_encoder *e = &hm2->encoder;
	double ticks;

	if (!e->num || !e->muxed_skew)
		return;
	ticks = *e->muxed_skew * (double)e->md->clock_freq * 1e-9 + 0.5;
	if (ticks < 0.0)
		ticks = 0.0;
	if (ticks > 15.0)
		ticks = 15.0;
	e->skew_ticks = (rtapi_u32)ticks;
}
