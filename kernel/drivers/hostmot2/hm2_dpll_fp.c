/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_dpll_fp.c - HM2DPLL register arithmetic (FP): base rate from base-freq-khz
 * (the thread's frequency until set), timer offsets as fractions of the period,
 * phase error in microseconds. Registers are written when their value changes. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "hal.h"
#include "hm2.h"

#define REG_BASE_RATE 0
#define REG_PHASE_ERR 1
#define REG_CONTROL0 2
#define REG_CONTROL1 3
#define REG_TIMERS12 4
#define REG_TIMERS34 5

void hm2_dpll_init_fp(struct hostmot2 *hm2)
{
	int i;

	if (!hm2->dpll.md)
		return;
	for (i = 0; i < 4; i++)
		*hm2->dpll.timer_us[i] = 0.0;
	*hm2->dpll.base_freq_khz = -1.0;	/* the thread frequency, at the first write() */
	*hm2->dpll.phase_error_us = 0.0;
}

void hm2_dpll_read_fp(struct hostmot2 *hm2)
{
	struct hm2_dpll *d = &hm2->dpll;

	if (!d->md)
		return;
	*d->ddsize = *d->control1_rd & 0xFF;
	*d->phase_error_us = (double)(rtapi_s32)*d->phase_rd * (double)hm2->period_ns /
			     (4294967296.0 * 1000.0);
}

static rtapi_u32 timer_field(double us, double period_us)
{
	double v = -us / period_us * 65536.0;

	if (v > 32767.0)
		v = 32767.0;
	if (v < -32768.0)
		v = -32768.0;
	return (rtapi_u32)(rtapi_s32)v & 0xFFFF;
}

static void put(struct hostmot2 *hm2, int reg, rtapi_u32 v, rtapi_u32 *written, int force)
{
	if (force || v != *written)
		hm2_write_now(hm2, hm2_md_addr(hm2->dpll.md, reg, 0), &v, 4);
	*written = v;
}

void hm2_dpll_write_fp(struct hostmot2 *hm2, long period)
{
	struct hm2_dpll *d = &hm2->dpll;
	double period_us = (double)period / 1000.0, rate;
	rtapi_u32 ddsize, prescale, zero = 0;
	int force = d->force;

	if (!d->md || period <= 0)
		return;
	if (*d->base_freq_khz <= 0.0)
		*d->base_freq_khz = 1e6 / (double)period;
	ddsize = *d->control1_rd & 0xFF;
	if (ddsize == 0 || ddsize > 48)
		ddsize = 32;
	prescale = *d->prescale ? *d->prescale : 1;
	rate = *d->base_freq_khz * 1000.0 * rtapi_pow(2.0, (double)ddsize) * (double)prescale /
	       (double)d->md->clock_freq;
	if (rate > 4294967295.0)
		rate = 4294967295.0;
	put(hm2, REG_BASE_RATE, (rtapi_u32)rate, &d->w_base_rate, force);
	put(hm2, REG_CONTROL0, ((prescale & 0xFF) << 24) | (*d->plimit & 0xFFFFFF), &d->w_control0, force);
	put(hm2, REG_CONTROL1, *d->time_const << 16, &d->w_control1, force);
	put(hm2, REG_TIMERS12, timer_field(*d->timer_us[0], period_us) |
			       timer_field(*d->timer_us[1], period_us) << 16, &d->w_timers12, force);
	put(hm2, REG_TIMERS34, timer_field(*d->timer_us[2], period_us) |
			       timer_field(*d->timer_us[3], period_us) << 16, &d->w_timers34, force);
	if (d->writes < 100) {
		/* let the loop start from zero phase error while the thread settles */
		hm2_write_now(hm2, hm2_md_addr(d->md, REG_PHASE_ERR, 0), &zero, 4);
		d->writes++;
	}
	d->force = 0;
}
