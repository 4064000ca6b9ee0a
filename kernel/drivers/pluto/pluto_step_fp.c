/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pluto_step_fp.c - pluto_step's read and write functions (pluto.md §5.4), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section.
 * Deliberate differences from the original driver (pluto.md marks them ⚠): the tap
 * bits of the timing word carry speedrange, so the rate sent is
 * steps/s x 1.6 us x 2^(11 + speedrange) and one step of feedback is 2^(11 +
 * speedrange) units (the original scaled only the rate, stepping 2^speedrange times
 * too slowly); the feed-forward is the commanded velocity (position difference over
 * the period) and the error term the position fed back this period against the
 * command (the original added one period of the last velocity, a following error of
 * one period at constant speed); step length, space and direction time round up to whole ticks and are
 * limited to the firmware's 4-bit fields; the outputs word arms the watchdog when
 * watchdog=1, as the page says. */
#include "pluto_step_fp.h"
#include "pluto_common.h"

static rtapi_s64 extend21(rtapi_s64 around, rtapi_u32 raw)
{
	rtapi_s32 d = (rtapi_s32)((raw - (rtapi_u32)around) & 0x1fffff);

	if (d >= 0x100000)
		d -= 0x200000;
	return around + d;
}

/* A time parameter in whole ticks, rounded up; rewritten when above the field. */
static rtapi_u32 ticks_of(hal_u32_t *ns)
{
	rtapi_u32 t = (*ns + PLUTO_STEP_TICK_NS - 1) / PLUTO_STEP_TICK_NS;

	if (t > PLUTO_STEP_TMAX) {
		t = PLUTO_STEP_TMAX;
		*ns = PLUTO_STEP_TMAX * PLUTO_STEP_TICK_NS;
	}
	return t;
}

static double safe_scale(double scale)
{
	return scale > -1e-20 && scale < 1e-20 ? 1.0 : scale;
}

static double fabs_(double x)
{
	return x < 0 ? -x : x;
}

COMP_FP_LOCAL void pluto_step_write(void *arg, long period)
{
	struct pluto_step *s = arg;
	unsigned int base = s->port.base;
	double period_s = period * 1e-9;
	double units = (double)(1L << (11 + s->speedrange));	/* per step */
	rtapi_u32 steplen = ticks_of(&s->steplen), stepspace = ticks_of(&s->stepspace);
	rtapi_u32 dirtime = ticks_of(&s->dirtime);
	double fmax = 1.0 / (PLUTO_STEP_TICK_NS * 1e-9 * (2 + steplen + stepspace));
	double fcap = 1024.0 / units / (PLUTO_STEP_TICK_NS * 1e-9);	/* rate field */
	double fread = 1048575.0 / units / period_s;	/* what one read can follow */
	rtapi_u16 out = s->watchdog_bit;
	int i;

	if (fcap < fmax)
		fmax = fcap;
	if (fread < fmax)
		fmax = fread;
	if (s->io.communication_error)
		return;
	pluto_addr(base, 0);
	for (i = 0; i < 4; i++) {
		struct pluto_stepgen *g = &s->sg[i];
		double scale = safe_scale(g->scale), cmd = *g->position_cmd;
		double ff = (cmd - g->old_cmd) / period_s;
		double err = *g->position_fb - cmd;	/* fb read this period */
		double v = ff - s->debug_2 * err / period_s, vmax = fmax / fabs_(scale);
		double r;
		int rate;

		g->old_cmd = cmd;
		if (g->maxvel < 0)
			g->maxvel = -g->maxvel;
		if (g->maxvel > vmax) {
			if (!g->maxvel_warned)
				rtapi_print_msg(RTAPI_MSG_ERR, "pluto_step: stepgen.%d.maxvel is above "
						"what the timings allow; lowered\n", i);
			g->maxvel_warned = 1;
			g->maxvel = vmax;
		}
		if (g->maxvel > 0 && g->maxvel < vmax)
			vmax = g->maxvel;
		if (v > vmax)
			v = vmax;
		if (v < -vmax)
			v = -vmax;
		r = v * scale * units * (PLUTO_STEP_TICK_NS * 1e-9);
		rate = r >= 0 ? (int)(r + 0.5) : -(int)(-r + 0.5);
		if (rate > 1024)
			rate = 1024;
		if (rate < -1024)
			rate = -1024;
		if (!*g->enable)
			rate = 0;
		if (i == 0)
			s->io.debug_1 = rate;
		pluto_write16(base, s->epp_wide, (rtapi_u16)(rate & 0xfff));
	}
	for (i = 0; i < 14; i++)
		out |= (rtapi_u16)(pluto_dout_level(&s->io, i) << i);
	pluto_write16(base, s->epp_wide, out);
	pluto_write16(base, s->epp_wide, (rtapi_u16)(steplen | s->speedrange << 6 |
				dirtime << 8 | (s->step_polarity ? 0x8000 : 0)));
}

COMP_FP_LOCAL void pluto_step_read(void *arg, long period)
{
	struct pluto_step *s = arg;
	double period_s = period * 1e-9;
	double units = (double)(1L << (11 + s->speedrange));
	rtapi_u32 word[4];
	int i;

	if (pluto_read_words(&s->port, s->epp_wide, &s->io, word))
		return;
	for (i = 0; i < 4; i++) {
		struct pluto_stepgen *g = &s->sg[i];
		double scale = safe_scale(g->scale), steps;
		rtapi_s64 prev = g->count64;

		g->count64 = extend21(prev, word[i] & 0x1fffff);
		*g->velocity_fb = (double)(g->count64 - prev) / units / scale / period_s;
		if (*g->reset)
			g->zero = g->count64;
		steps = (double)(g->count64 - g->zero) / units;
		*g->counts = (rtapi_s32)steps;
		*g->position_fb = steps / scale;
	}
	pluto_read_din(&s->port, s->epp_wide, &s->io);
	s->io.debug_0 = (rtapi_s32)word[0];
}
