/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_encoder.c - quadrature encoder (GTag 4) and muxed encoder (GTag 12), hostmot2.md
 * 7.4: MD checks, HAL objects and the integer register writes (control words,
 * timestamp divider, filter rate with the mux skew, DPLL timer select). The counting,
 * position and velocity arithmetic is in hm2_encoder_fp.c. Both kinds have the same
 * registers and the same HAL names (encoder.NN); a muxed unit's pin set carries two
 * encoders (2u and 2u + 1), chosen by the global select pins, and the module pins are
 * muxed-sample-frequency and muxed-skew instead of sample-frequency. Like LinuxCNC,
 * a firmware with both kinds is refused. */
#include "rtapi.h"
#include "hal.h"
#include "hm2.h"

#define REG_COUNTER 0
#define REG_CONTROL 1
#define REG_TSDIV 2
#define REG_TSCOUNT 3
#define REG_FILTER 4
#define REG_TIMER 5

#define CTL_LATCH_PROBE (1u << 13)
#define CTL_PROBE_POL (1u << 12)
#define CTL_FILTER (1u << 11)
#define CTL_COUNTER_MODE (1u << 10)
#define CTL_INDEX_MASK (1u << 9)
#define CTL_INDEX_MASK_POL (1u << 8)
#define CTL_JUST_ONCE (1u << 6)
#define CTL_LATCH_INDEX (1u << 4)
#define CTL_INDEX_POL (1u << 3)

int hm2_encoder_parse(struct hostmot2 *hm2, const struct hm2_md *md)
{
	struct hm2_encoder *e = &hm2->encoder;
	char err[HM2_ERRLEN];
	int n, rc;

	if (e->md) {
		HM2_ERR(hm2, "inconsistent firmware: it has both an encoder and a muxed encoder module");
		return -EINVAL;
	}
	if (hm2_md_is_consistent(md, err, sizeof(err))) {
		HM2_ERR(hm2, "%s", err);
		return -EINVAL;
	}
	n = hm2_config_instances(&hm2->cfg, HM2_NUM_ENCODERS, md->instances, err, sizeof(err));
	if (n < 0) {
		HM2_ERR(hm2, "%s", err);
		return n;
	}
	e->muxed = md->gtag == HM2_GTAG_MUXED_ENCODER;
	if (!e->muxed && md->version == 1)
		HM2_WARN(hm2, "encoder: firmware version 1 has a buggy index; please upgrade");
	if (e->muxed && md->version == 2)
		HM2_WARN(hm2, "muxed encoder: firmware version 2 gives bad velocity; please upgrade");
	e->md = md;
	e->num = n;
	if (!n)
		return 0;
	e->inst = hal_malloc(n * sizeof(*e->inst));
	if (!e->inst)
		return -ENOMEM;
	if (e->muxed) {
		/* two encoders per physical pin set; the select pins serve them all */
		hm2_pins_allocate(hm2, HM2_GTAG_MUXED_ENCODER, (n + 1) / 2);
		hm2_pins_allocate(hm2, HM2_GTAG_MUXED_ENCODER_SEL, n);
	} else {
		hm2_pins_allocate(hm2, HM2_GTAG_ENCODER, n);
	}
	/* TSCount first, so the counters are never older than the timestamp */
	rc = hm2_tram_add_read(hm2, hm2_md_addr(md, REG_TSCOUNT, 0), 4, &e->tscount_rd);
	if (!rc)
		rc = hm2_tram_add_read(hm2, hm2_md_addr(md, REG_COUNTER, 0), n * 4, &e->counter_rd);
	if (!rc)
		rc = hm2_tram_add_read(hm2, hm2_md_addr(md, REG_CONTROL, 0), n * 4, &e->control_rd);
	return rc;
}

int hm2_encoder_export(struct hostmot2 *hm2)
{
	struct hm2_encoder *e = &hm2->encoder;
	const char *b = hm2->llio->name;
	int id = hm2->llio->comp_id, i, rc = 0;

	if (!e->num)
		return 0;
	for (i = 0; i < e->num && !rc; i++) {
		struct hm2_encoder_inst *x = &e->inst[i];
		char p[HAL_NAME_LEN + 1];

		rtapi_snprintf(p, sizeof(p), "%s.encoder.%02d", b, i);
		rc = hal_pin_s32_newf(HAL_OUT, &x->count, id, "%s.count", p);
		if (!rc) rc = hal_pin_s32_newf(HAL_OUT, &x->rawcounts, id, "%s.rawcounts", p);
		if (!rc) rc = hm2_alias_pin(hm2, p, "rawcounts", "rawcount");	/* the EMC2 page's name */
		if (!rc) rc = hal_pin_float_newf(HAL_OUT, &x->position, id, "%s.position", p);
		if (!rc) rc = hal_pin_float_newf(HAL_OUT, &x->position_interpolated, id,
						 "%s.position-interpolated", p);
		if (!rc) rc = hal_pin_float_newf(HAL_OUT, &x->position_latched, id, "%s.position-latched", p);
		if (!rc) rc = hal_pin_float_newf(HAL_OUT, &x->velocity, id, "%s.velocity", p);
		if (!rc) rc = hal_pin_float_newf(HAL_OUT, &x->velocity_rpm, id, "%s.velocity-rpm", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_IN, &x->reset, id, "%s.reset", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_IO, &x->index_enable, id, "%s.index-enable", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_IO, &x->probe_enable, id, "%s.probe-enable", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_OUT, &x->input_a, id, "%s.input-a", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_OUT, &x->input_b, id, "%s.input-b", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_OUT, &x->input_index, id, "%s.input-index", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_IN, &x->quad_error_enable, id, "%s.quad-error-enable", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_OUT, &x->quad_error, id, "%s.quad-error", p);
		if (!rc) rc = hal_param_float_newf(HAL_RW, &x->scale, id, "%s.scale", p);
		if (!rc) rc = hal_param_bit_newf(HAL_RW, &x->index_invert, id, "%s.index-invert", p);
		if (!rc) rc = hal_param_bit_newf(HAL_RW, &x->index_mask, id, "%s.index-mask", p);
		if (!rc) rc = hal_param_bit_newf(HAL_RW, &x->index_mask_invert, id, "%s.index-mask-invert", p);
		if (!rc) rc = hal_param_bit_newf(HAL_RW, &x->counter_mode, id, "%s.counter-mode", p);
		if (!rc) rc = hal_param_bit_newf(HAL_RW, &x->filter, id, "%s.filter", p);
		if (!rc) rc = hal_param_float_newf(HAL_RW, &x->vel_timeout, id, "%s.vel-timeout", p);
		if (!rc) rc = hal_param_bit_newf(HAL_RW, &x->probe_invert, id, "%s.probe-invert", p);
		x->filter = 1;
		x->written_control = 0xFFFFFFFFu;	/* written at the first write() */
	}
	if (!rc)
		rc = hal_pin_u32_newf(HAL_IN, &e->sample_frequency, id, "%s.encoder.%ssample-frequency", b,
				      e->muxed ? "muxed-" : "");
	if (!rc && e->muxed && (e->md->version & 0x7F) > 3)
		rc = hal_pin_float_newf(HAL_IN, &e->muxed_skew, id, "%s.encoder.muxed-skew", b);
	if (!rc)
		rc = hal_pin_bit_newf(HAL_IN, &e->hires_timestamp, id, "%s.encoder.hires-timestamp", b);
	if (!rc && hm2->dpll.md) {
		e->has_timer = 1;
		rc = hal_param_s32_newf(HAL_RW, &e->timer_number, id, "%s.encoder.timer-number", b);
	}
	if (rc)
		return rc;
	*e->sample_frequency = e->muxed ? 8000000 : 25000000;
	e->timer_number = -1;
	return 0;
}

static rtapi_u32 control_word(const struct hm2_encoder_inst *x)
{
	rtapi_u32 c = 0;

	if (*x->probe_enable && !*x->index_enable)
		c |= CTL_LATCH_PROBE;
	if (x->probe_invert)
		c |= CTL_PROBE_POL;
	if (x->filter)
		c |= CTL_FILTER;
	if (x->counter_mode)
		c |= CTL_COUNTER_MODE;
	if (x->index_mask)
		c |= CTL_INDEX_MASK;
	if (x->index_mask_invert)
		c |= CTL_INDEX_MASK_POL;
	if (*x->index_enable || *x->probe_enable)
		c |= CTL_JUST_ONCE;
	if (*x->index_enable)
		c |= CTL_LATCH_INDEX;
	if (x->index_invert)
		c |= CTL_INDEX_POL;
	return c;
}

static void write_module_regs(struct hostmot2 *hm2, int force)
{
	struct hm2_encoder *e = &hm2->encoder;
	rtapi_u32 clk = e->md->clock_freq, v;
	int hires = *e->hires_timestamp;

	if (force || hires != e->written_hires) {
		e->tsdiv = clk / (hires ? 10000000u : 2000000u);
		e->tsdiv = e->tsdiv >= 2 ? e->tsdiv - 2 : 0;
		hm2_write_now(hm2, hm2_md_addr(e->md, REG_TSDIV, 0), &e->tsdiv, 4);
		e->written_hires = hires;
	}
	if (force || *e->sample_frequency != e->written_sample_frequency ||
	    e->skew_ticks != e->written_skew) {
		rtapi_u32 f = *e->sample_frequency ? *e->sample_frequency : 1;
		rtapi_u32 q = clk / f;

		v = q <= 1 ? 0xFFF : (q - 2 > 0xFFE ? 0xFFE : q - 2);
		if (e->muxed_skew)
			v |= e->skew_ticks << 28;	/* mux skew, ClockLow periods */
		hm2_write_now(hm2, hm2_md_addr(e->md, REG_FILTER, 0), &v, 4);
		e->written_sample_frequency = *e->sample_frequency;
		e->written_skew = e->skew_ticks;
	}
	if (e->has_timer && (force || e->timer_number != e->written_timer)) {
		int t = e->timer_number;

		v = (t >= 0 && t <= 4) ? (0x8000u | ((rtapi_u32)t << 12)) : 0;
		hm2_write_now(hm2, hm2_md_addr(e->md, REG_TIMER, 0), &v, 4);
		e->written_timer = t;
	}
}

void hm2_encoder_force_write(struct hostmot2 *hm2)
{
	struct hm2_encoder *e = &hm2->encoder;
	int i;

	if (!e->num)
		return;
	write_module_regs(hm2, 1);
	for (i = 0; i < e->num; i++)
		e->inst[i].written_control = 0xFFFFFFFFu;
	hm2_encoder_write(hm2);
}

/* On-change control words; a pending quadrature error is cleared (by writing bit
 * 15 = 0) while quad-error-enable is false. */
void hm2_encoder_write(struct hostmot2 *hm2)
{
	struct hm2_encoder *e = &hm2->encoder;
	int i;

	if (!e->num)
		return;
	write_module_regs(hm2, 0);
	for (i = 0; i < e->num; i++) {
		struct hm2_encoder_inst *x = &e->inst[i];
		rtapi_u32 c = control_word(x);
		int clear_qe = !*x->quad_error_enable && (e->control_rd[i] & 0x8000u);

		if (c != x->written_control || clear_qe) {
			hm2_write_now(hm2, hm2_md_addr(e->md, REG_CONTROL, i), &c, 4);
			x->written_control = c;
		}
	}
}
