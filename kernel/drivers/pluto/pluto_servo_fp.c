/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pluto_servo_fp.c - pluto_servo's read and write functions (pluto.md §4.6), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section. */
#include "pluto_servo_fp.h"
#include "pluto_common.h"

/* The value congruent to 'low' modulo 2^14 nearest to 'around' (max step +-8191). */
static rtapi_s64 extend14(rtapi_s64 around, rtapi_u32 low)
{
	rtapi_s32 d = (rtapi_s32)((low - (rtapi_u32)around) & 0x3fff);

	if (d >= 0x2000)
		d -= 0x4000;
	return around + d;
}

static double safe_scale(double scale)
{
	return scale > -1e-20 && scale < 1e-20 ? 1.0 : scale;
}

/* The PWM word of channel 'ch'; corrects max-dc and min-dc into range. */
static rtapi_u32 pwm_word(struct pluto_servo *s, int ch)
{
	struct pluto_pwm *p = &s->pwm[ch];
	rtapi_u32 w = 0;

	if (p->max_dc > 1.0)
		p->max_dc = 1.0;
	if (p->max_dc < 0.0)
		p->max_dc = 0.0;
	if (p->min_dc < 0.0)
		p->min_dc = 0.0;
	if (p->min_dc > p->max_dc)
		p->min_dc = p->max_dc;
	if (*p->enable) {
		double d = *p->value / safe_scale(p->scale) + p->offset;
		int m;

		if (d > p->max_dc)
			d = p->max_dc;
		if (d < -p->max_dc)
			d = -p->max_dc;
		if (d > 0 && d < p->min_dc)
			d = p->min_dc;
		if (d < 0 && d > -p->min_dc)
			d = -p->min_dc;
		m = (int)(2047 * d);		/* toward zero */
		if (m > 2047)
			m = 2047;
		if (m < -2047)
			m = -2047;
		if (d < 0)
			w = (p->pwmdir ? 0x2000 : 0x8000) | (rtapi_u32)-m;
		else
			w = (rtapi_u32)m;
	}
	if (s->is_pdm)
		w |= 0x4000;
	/* UP and DOWN of channel ch are dout 10 + 2ch and 11 + 2ch */
	w ^= (rtapi_u32)pluto_dout_level(&s->io, 10 + 2 * ch) << 12;
	w ^= (rtapi_u32)pluto_dout_level(&s->io, 11 + 2 * ch) << 13;
	return w;
}

COMP_FP_LOCAL void pluto_servo_write(void *arg, long period)
{
	struct pluto_servo *s = arg;
	unsigned int base = s->port.base;
	rtapi_u16 out = s->control_bits | (s->z_polarity ? 0x8000 : 0);
	int k;

	if (s->io.communication_error)
		return;		/* outputs frozen; the watchdog will bite */
	pluto_addr(base, 0);
	pluto_write32(base, s->epp_wide, pwm_word(s, 0) | pwm_word(s, 1) << 16);
	pluto_write32(base, s->epp_wide, pwm_word(s, 2) | pwm_word(s, 3) << 16);
	for (k = 0; k < 10; k++)
		out |= (rtapi_u16)(pluto_dout_level(&s->io, k) << k);
	pluto_write16(base, s->epp_wide, out);
}

static void update_encoder(struct pluto_encoder *e, rtapi_u32 word, double period_s)
{
	rtapi_s64 prev = e->count64;
	double scale = safe_scale(e->scale);

	e->count64 = extend14(prev, word & 0x3fff);
	if (word & (1u << 28)) {
		e->index64 = extend14(e->count64, (word >> 14) & 0x3fff);
		if (*e->index_enable) {
			*e->index_enable = 0;
			e->zero = e->index64;
		}
	}
	if (*e->reset) {
		*e->velocity = 0;
		e->zero = e->count64;
	} else {
		*e->velocity = (double)(e->count64 - prev) / scale / period_s;
	}
	*e->count = (rtapi_s32)(e->count64 - e->zero);
	*e->position = *e->count / scale;
}

COMP_FP_LOCAL void pluto_servo_read(void *arg, long period)
{
	struct pluto_servo *s = arg;
	double period_s = period * 1e-9;
	rtapi_u32 word[4];
	int i;

	if (pluto_read_words(&s->port, s->epp_wide, &s->io, word))
		return;
	for (i = 0; i < 4; i++)
		update_encoder(&s->enc[i], word[i], period_s);
	pluto_read_din(&s->port, s->epp_wide, &s->io);
	s->io.debug_0 = (rtapi_s32)word[0];
	s->io.debug_1 = (rtapi_s32)s->enc[0].count64;
}
