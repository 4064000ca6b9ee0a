/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_pwmgen.c - PWMGen (GTag 6, hostmot2.md 7.6): MD checks, HAL objects and the
 * integer setup registers (per-instance mode, PWM/PDM master DDS, enable bits),
 * rewritten together whenever any of them changes. The duty-cycle arithmetic of the
 * per-cycle value registers is in hm2_pwmgen_fp.c. */
#include "rtapi.h"
#include "hal.h"
#include "hm2.h"

#define REG_VALUE 0
#define REG_MODE 1
#define REG_PWM_DDS 2
#define REG_PDM_DDS 3
#define REG_ENABLE 4

int hm2_pwmgen_parse(struct hostmot2 *hm2, const struct hm2_md *md)
{
	struct hm2_pwmgen *g = &hm2->pwmgen;
	char err[HM2_ERRLEN];
	int n;

	if (hm2_md_is_consistent(md, err, sizeof(err))) {
		HM2_ERR(hm2, "%s", err);
		return -EINVAL;
	}
	n = hm2_config_instances(&hm2->cfg, HM2_NUM_PWMGENS, md->instances, err, sizeof(err));
	if (n < 0) {
		HM2_ERR(hm2, "%s", err);
		return n;
	}
	g->md = md;
	g->num = n;
	if (!n)
		return 0;
	g->inst = hal_malloc(n * sizeof(*g->inst));
	if (!g->inst)
		return -ENOMEM;
	hm2_pins_allocate(hm2, HM2_GTAG_PWMGEN, n);
	return hm2_tram_add_write(hm2, hm2_md_addr(md, REG_VALUE, 0), n * 4, &g->value_wr);
}

int hm2_pwmgen_export(struct hostmot2 *hm2)
{
	struct hm2_pwmgen *g = &hm2->pwmgen;
	const char *b = hm2->llio->name;
	int id = hm2->llio->comp_id, i, rc = 0;

	if (!g->num)
		return 0;
	for (i = 0; i < g->num && !rc; i++) {
		struct hm2_pwmgen_inst *x = &g->inst[i];
		char p[HAL_NAME_LEN + 1];

		rtapi_snprintf(p, sizeof(p), "%s.pwmgen.%02d", b, i);
		rc = hal_pin_bit_newf(HAL_IN, &x->enable, id, "%s.enable", p);
		if (!rc) rc = hal_pin_float_newf(HAL_IN, &x->value, id, "%s.value", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_IN, &x->offset_mode, id, "%s.offset-mode", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_IN, &x->dither, id, "%s.dither", p);
		if (!rc) rc = hal_param_float_newf(HAL_RW, &x->scale, id, "%s.scale", p);
		if (!rc) rc = hal_param_s32_newf(HAL_RW, &x->output_type, id, "%s.output-type", p);
		x->output_type = 1;
	}
	if (!rc)
		rc = hal_param_u32_newf(HAL_RW, &g->pwm_frequency, id, "%s.pwmgen.pwm_frequency", b);
	if (!rc)
		rc = hal_param_u32_newf(HAL_RW, &g->pdm_frequency, id, "%s.pwmgen.pdm_frequency", b);
	g->pwm_frequency = g->pdm_frequency = 20000;
	g->force = 1;
	return rc;
}

/* PWM: the widest of 12..9 bits whose DDS fits 16 bits; else clip the frequency.
 * PDM: DDS = f x 65536 / clock, 1..65535. Params are rewritten to what is used. */
static void frequencies(struct hm2_pwmgen *g)
{
	rtapi_u64 clk = g->md->clock_freq, dds = 0;
	int bits;

	if (!g->pwm_frequency)
		g->pwm_frequency = 1;
	for (bits = 12; bits >= 9; bits--) {
		dds = rtapi_div_u64(((rtapi_u64)g->pwm_frequency << (16 + bits)), (rtapi_u32)clk);
		if (dds < 65536)
			break;
	}
	if (bits < 9) {
		bits = 9;
		dds = 65535;
		g->pwm_frequency = (rtapi_u32)rtapi_div_u64(clk * 65535, 65536u * 512u);
	}
	g->bits = bits;
	g->pwm_dds = dds ? (rtapi_u32)dds : 1;
	dds = rtapi_div_u64((rtapi_u64)g->pdm_frequency << 16, (rtapi_u32)clk);
	if (dds < 1)
		dds = 1;
	if (dds > 65535) {
		dds = 65535;
		g->pdm_frequency = (rtapi_u32)rtapi_div_u64(clk * 65535, 65536u);
	}
	g->pdm_dds = (rtapi_u32)dds;
}

static rtapi_u32 mode_word(struct hostmot2 *hm2, int i)
{
	struct hm2_pwmgen *g = &hm2->pwmgen;
	struct hm2_pwmgen_inst *x = &g->inst[i];
	rtapi_u32 m;

	switch (x->output_type) {
	case 1: m = (0u << 3) | (1u << 5); break;
	case 2: m = (2u << 3) | (1u << 5); break;
	case 3: m = 3u << 3; break;
	case 4: m = (1u << 3) | (1u << 5); break;
	default:
		HM2_ERR(hm2, "pwmgen.%02d: output-type %d is not 1..4; using 1", i, x->output_type);
		x->output_type = 1;
		m = 1u << 5;
	}
	m |= x->output_type == 3 ? 3u : (rtapi_u32)(g->bits - 9);
	if (*x->dither && g->md->version >= 1)
		m |= 1u << 6;
	return m;
}

void hm2_pwmgen_write(struct hostmot2 *hm2)
{
	struct hm2_pwmgen *g = &hm2->pwmgen;
	rtapi_u32 enable = 0, mode;
	int i, change = g->force;

	if (!g->num)
		return;
	if (g->pwm_frequency != g->w_pwm_frequency || g->pdm_frequency != g->w_pdm_frequency) {
		frequencies(g);
		change = 1;
	}
	for (i = 0; i < g->num; i++) {
		if (*g->inst[i].enable)
			enable |= 1u << i;
		if (mode_word(hm2, i) != g->inst[i].w_mode)
			change = 1;
	}
	if (enable != g->w_enable)
		change = 1;
	if (!change)
		return;
	frequencies(g);
	for (i = 0; i < g->num; i++) {
		mode = mode_word(hm2, i);
		hm2_write_now(hm2, hm2_md_addr(g->md, REG_MODE, i), &mode, 4);
		g->inst[i].w_mode = mode;
	}
	hm2_write_now(hm2, hm2_md_addr(g->md, REG_PWM_DDS, 0), &g->pwm_dds, 4);
	hm2_write_now(hm2, hm2_md_addr(g->md, REG_PDM_DDS, 0), &g->pdm_dds, 4);
	hm2_write_now(hm2, hm2_md_addr(g->md, REG_ENABLE, 0), &enable, 4);
	g->w_enable = enable;
	g->w_pwm_frequency = g->pwm_frequency;
	g->w_pdm_frequency = g->pdm_frequency;
	g->force = 0;
}

void hm2_pwmgen_force_write(struct hostmot2 *hm2)
{
	hm2->pwmgen.force = 1;
	hm2_pwmgen_write(hm2);
}
