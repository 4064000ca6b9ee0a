/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_tppwm.c - three-phase PWM, "3pwmgen" (GTag 19, hostmot2.md 7.7): MD checks, HAL
 * objects and the integer register writes. Per instance: the value word (three 10-bit
 * duties, every cycle), enable/fault (read every cycle, enable written on change) and
 * setup (dead time, fault polarity, ADC sample time, on change); module-wide the rate
 * DDS. The duty and setup arithmetic is in hm2_tppwm_fp.c. The hardware clears enable
 * when the fault input trips; the driver writes enable again only when the enable pin
 * changes, so the fault stays latched until enable is set high again. */
#include "rtapi.h"
#include "hal.h"
#include "hm2.h"

#define REG_VALUE 0
#define REG_ENABLE 1
#define REG_SETUP 2
#define REG_RATE 3
#define STATUS_FAULT 2u
#define FREQ_MIN 1000u

int hm2_tppwm_parse(struct hostmot2 *hm2, const struct hm2_md *md)
{
	struct hm2_tppwm *t = &hm2->tppwm;
	char err[HM2_ERRLEN];
	int n, rc;

	if (hm2_md_is_consistent(md, err, sizeof(err))) {
		HM2_ERR(hm2, "%s", err);
		return -EINVAL;
	}
	n = hm2_config_instances(&hm2->cfg, HM2_NUM_3PWMGENS, md->instances, err, sizeof(err));
	if (n < 0) {
		HM2_ERR(hm2, "%s", err);
		return n;
	}
	t->md = md;
	t->num = n;
	if (!n)
		return 0;
	t->inst = hal_malloc(n * sizeof(*t->inst));
	if (!t->inst)
		return -ENOMEM;
	hm2_pins_allocate(hm2, HM2_GTAG_TPPWM, n);
	rc = hm2_tram_add_write(hm2, hm2_md_addr(md, REG_VALUE, 0), n * 4, &t->value_wr);
	if (!rc)
		rc = hm2_tram_add_read(hm2, hm2_md_addr(md, REG_ENABLE, 0), n * 4, &t->status_rd);
	return rc;
}

int hm2_tppwm_export(struct hostmot2 *hm2)
{
	struct hm2_tppwm *t = &hm2->tppwm;
	const char *b = hm2->llio->name;
	int id = hm2->llio->comp_id, i, rc = 0;

	if (!t->num)
		return 0;
	for (i = 0; i < t->num && !rc; i++) {
		struct hm2_tppwm_inst *x = &t->inst[i];
		char p[HAL_NAME_LEN + 1];

		rtapi_snprintf(p, sizeof(p), "%s.3pwmgen.%02d", b, i);
		rc = hal_pin_float_newf(HAL_IN, &x->a_value, id, "%s.A-value", p);
		if (!rc) rc = hal_pin_float_newf(HAL_IN, &x->b_value, id, "%s.B-value", p);
		if (!rc) rc = hal_pin_float_newf(HAL_IN, &x->c_value, id, "%s.C-value", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_IN, &x->enable, id, "%s.enable", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_OUT, &x->fault, id, "%s.fault", p);
		if (!rc) rc = hal_param_u32_newf(HAL_RW, &x->deadtime, id, "%s.deadtime", p);
		if (!rc) rc = hal_param_float_newf(HAL_RW, &x->scale, id, "%s.scale", p);
		if (!rc) rc = hal_param_bit_newf(HAL_RW, &x->fault_invert, id, "%s.fault-invert", p);
		/* float, as LinuxCNC creates it: the page's "u32" cannot hold its default 0.5 */
		if (!rc) rc = hal_param_float_newf(HAL_RW, &x->sample_time, id, "%s.sample-time", p);
		x->deadtime = 5000;
	}
	if (!rc)
		rc = hal_param_u32_newf(HAL_RW, &t->frequency, id, "%s.3pwmgen.frequency", b);
	t->frequency = 20000;
	t->force = 1;
	return rc;
}

/* rate DDS = f x 65536 x 2048 / ClockHigh (16 bits); f clipped to 1 kHz..max */
static void rate(struct hm2_tppwm *t)
{
	rtapi_u64 clk = t->md->clock_freq;
	rtapi_u32 fmax = (rtapi_u32)rtapi_div_u64(clk * 65535, 65536u * 2048u);

	if (t->frequency < FREQ_MIN)
		t->frequency = FREQ_MIN;
	if (t->frequency > fmax)
		t->frequency = fmax;
	t->dds = (rtapi_u32)rtapi_div_u64((rtapi_u64)t->frequency << 27, (rtapi_u32)clk);
	if (!t->dds)
		t->dds = 1;
}

/* Dead-time register = ns x ClockHigh x DDS / (2 x 65536 x 1e9), 9 bits. */
rtapi_u32 hm2_tppwm_deadtime_reg(struct hostmot2 *hm2, int i)
{
	struct hm2_tppwm *t = &hm2->tppwm;
	rtapi_u64 ns = t->inst[i].deadtime > 10000000u ? 10000000u : t->inst[i].deadtime;
	rtapi_u64 v = rtapi_div_u64(ns * (t->md->clock_freq / 1000u) * t->dds, 131072u);

	v = rtapi_div_u64(v, 1000000u);
	return v > 511 ? 511 : (rtapi_u32)v;
}

void hm2_tppwm_write(struct hostmot2 *hm2)
{
	struct hm2_tppwm *t = &hm2->tppwm;
	int i, force = t->force;

	if (!t->num)
		return;
	if (force || t->frequency != t->w_frequency) {
		rate(t);
		hm2_write_now(hm2, hm2_md_addr(t->md, REG_RATE, 0), &t->dds, 4);
		t->w_frequency = t->frequency;
		force = 1;	/* the dead time depends on the rate */
	}
	for (i = 0; i < t->num; i++) {
		struct hm2_tppwm_inst *x = &t->inst[i];
		rtapi_u32 en = *x->enable;

		if (force || x->setup != x->w_setup) {
			hm2_write_now(hm2, hm2_md_addr(t->md, REG_SETUP, i), &x->setup, 4);
			x->w_setup = x->setup;
		}
		if (force || en != x->w_enable) {
			hm2_write_now(hm2, hm2_md_addr(t->md, REG_ENABLE, i), &en, 4);
			x->w_enable = en;
		}
	}
	t->force = 0;
}

void hm2_tppwm_force_write(struct hostmot2 *hm2)
{
	hm2->tppwm.force = 1;
	if (hm2->tppwm.num && !hm2->tppwm.dds)
		rate(&hm2->tppwm);
	hm2_tppwm_write(hm2);
}

void hm2_tppwm_read(struct hostmot2 *hm2)
{
	struct hm2_tppwm *t = &hm2->tppwm;
	int i;

	for (i = 0; i < t->num; i++)
		*t->inst[i].fault = !!(t->status_rd[i] & STATUS_FAULT);
}
