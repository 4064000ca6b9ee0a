/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_stepgen.c - StepGen (GTag 5, hostmot2.md 7.5): MD checks, HAL objects and the
 * integer register writes (timing in ns -> clocks, mode, step table, master DDS,
 * DPLL timer). The motion arithmetic (rate from position/velocity command, feedback
 * from the accumulator) is in hm2_stepgen_fp.c. */
#include "rtapi.h"
#include "hal.h"
#include "hm2.h"

#define REG_RATE 0
#define REG_ACCUM 1
#define REG_MODE 2
#define REG_DIRSETUP 3
#define REG_DIRHOLD 4
#define REG_STEPLEN 5
#define REG_STEPSPACE 6
#define REG_TABLE 7
#define REG_TABLELEN 8
#define REG_MASTERDDS 9
#define REG_TIMER 10
#define TIMING_MAX 0x3FFFu

int hm2_stepgen_parse(struct hostmot2 *hm2, const struct hm2_md *md)
{
	struct hm2_stepgen *s = &hm2->stepgen;
	char err[HM2_ERRLEN];
	int n, rc;

	if (hm2_md_is_consistent(md, err, sizeof(err))) {
		HM2_ERR(hm2, "%s", err);
		return -EINVAL;
	}
	n = hm2_config_instances(&hm2->cfg, HM2_NUM_STEPGENS, md->instances, err, sizeof(err));
	if (n < 0) {
		HM2_ERR(hm2, "%s", err);
		return n;
	}
	if (md->version < 2)
		HM2_WARN(hm2, "stepgen: firmware version %u is old; please upgrade", md->version);
	s->md = md;
	s->num = n;
	if (!n)
		return 0;
	s->inst = hal_malloc(n * sizeof(*s->inst));
	if (!s->inst)
		return -ENOMEM;
	hm2_pins_allocate(hm2, HM2_GTAG_STEPGEN, n);
	rc = hm2_tram_add_read(hm2, hm2_md_addr(md, REG_ACCUM, 0), n * 4, &s->acc_rd);
	if (!rc)
		rc = hm2_tram_add_write(hm2, hm2_md_addr(md, REG_RATE, 0), n * 4, &s->rate_wr);
	return rc;
}

static rtapi_u32 ticks_to_ns(rtapi_u32 ticks, rtapi_u32 clk)
{
	return (rtapi_u32)rtapi_div_u64((rtapi_u64)ticks * 1000000000u, clk);
}

int hm2_stepgen_export(struct hostmot2 *hm2)
{
	struct hm2_stepgen *s = &hm2->stepgen;
	const char *b = hm2->llio->name;
	int id = hm2->llio->comp_id, i, j, rc = 0;
	int index_probe = s->md && s->md->version == 0xC2;
	int swap = s->md && (s->md->version == 0x42 || s->md->version == 0xC2);

	if (!s->num)
		return 0;
	for (i = 0; i < s->num && !rc; i++) {
		struct hm2_stepgen_inst *x = &s->inst[i];
		rtapi_u32 slow = ticks_to_ns(TIMING_MAX, s->md->clock_freq);
		char p[HAL_NAME_LEN + 1];

		rtapi_snprintf(p, sizeof(p), "%s.stepgen.%02d", b, i);
		rc = hal_pin_float_newf(HAL_IN, &x->position_cmd, id, "%s.position-cmd", p);
		if (!rc) rc = hal_pin_float_newf(HAL_IN, &x->velocity_cmd, id, "%s.velocity-cmd", p);
		if (!rc) rc = hal_pin_s32_newf(HAL_OUT, &x->counts, id, "%s.counts", p);
		if (!rc) rc = hal_pin_float_newf(HAL_OUT, &x->position_fb, id, "%s.position-fb", p);
		if (!rc) rc = hal_pin_float_newf(HAL_OUT, &x->position_latched, id, "%s.position-latched", p);
		if (!rc) rc = hal_pin_float_newf(HAL_OUT, &x->velocity_fb, id, "%s.velocity-fb", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_IN, &x->enable, id, "%s.enable", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_IN, &x->position_reset, id, "%s.position-reset", p);
		if (!rc) rc = hal_pin_bit_newf(HAL_IN, &x->control_type, id, "%s.control-type", p);
		if (!rc && index_probe) {
			rc = hal_pin_bit_newf(HAL_IO, &x->index_enable, id, "%s.index-enable", p);
			if (!rc) rc = hal_pin_bit_newf(HAL_IO, &x->probe_enable, id, "%s.probe-enable", p);
			if (!rc) rc = hal_param_bit_newf(HAL_RW, &x->index_invert, id, "%s.index-invert", p);
			if (!rc) rc = hal_param_bit_newf(HAL_RW, &x->probe_invert, id, "%s.probe-invert", p);
		}
		if (!rc) rc = hal_param_float_newf(HAL_RW, &x->position_scale, id, "%s.position-scale", p);
		if (!rc) rc = hal_param_float_newf(HAL_RW, &x->maxvel, id, "%s.maxvel", p);
		if (!rc) rc = hal_param_float_newf(HAL_RW, &x->maxaccel, id, "%s.maxaccel", p);
		if (!rc) rc = hal_param_u32_newf(HAL_RW, &x->steplen, id, "%s.steplen", p);
		if (!rc) rc = hal_param_u32_newf(HAL_RW, &x->stepspace, id, "%s.stepspace", p);
		if (!rc) rc = hal_param_u32_newf(HAL_RW, &x->dirsetup, id, "%s.dirsetup", p);
		if (!rc) rc = hal_param_u32_newf(HAL_RW, &x->dirhold, id, "%s.dirhold", p);
		if (!rc) rc = hal_param_u32_newf(HAL_RW, &x->step_type, id, "%s.step_type", p);
		if (!rc && swap)
			rc = hal_param_bit_newf(HAL_RW, &x->swap_step_dir, id, "%s.swap_step_dir", p);
		for (j = 0; j < 4 && !rc; j++)
			rc = hal_param_u32_newf(HAL_RW, &x->table_data[j], id, "%s.table-data-%d", p, j);
		x->steplen = x->stepspace = x->dirsetup = x->dirhold = slow;
		x->force = 1;
	}
	if (!rc && hm2->dpll.md) {
		s->has_timer = 1;
		rc = hal_param_s32_newf(HAL_RW, &s->timer_number, id, "%s.stepgen.timer-number", b);
		s->timer_number = -1;
	}
	return rc;
}

/* ns -> clocks, at most 14 bits; the param is rewritten to the time it gets */
static rtapi_u32 timing(hal_u32_t *ns, rtapi_u32 clk)
{
	rtapi_u64 t = rtapi_div_u64((rtapi_u64)*ns * clk, 1000000000u);

	if (t > TIMING_MAX) {
		t = TIMING_MAX;
		*ns = ticks_to_ns(TIMING_MAX, clk);
	}
	return (rtapi_u32)t;
}

static void write_inst(struct hostmot2 *hm2, int i)
{
	struct hm2_stepgen *s = &hm2->stepgen;
	struct hm2_stepgen_inst *x = &s->inst[i];
	rtapi_u32 clk = s->md->clock_freq, v, mode, sum, type = x->step_type;
	int j;

	v = timing(&x->steplen, clk);
	if (x->force || v != x->w_steplen)
		hm2_write_now(hm2, hm2_md_addr(s->md, REG_STEPLEN, i), &v, 4);
	x->w_steplen = v;
	v = timing(&x->stepspace, clk);
	if (x->force || v != x->w_stepspace)
		hm2_write_now(hm2, hm2_md_addr(s->md, REG_STEPSPACE, i), &v, 4);
	x->w_stepspace = v;
	v = timing(&x->dirsetup, clk);
	if (x->force || v != x->w_dirsetup)
		hm2_write_now(hm2, hm2_md_addr(s->md, REG_DIRSETUP, i), &v, 4);
	x->w_dirsetup = v;
	v = timing(&x->dirhold, clk);
	if (x->force || v != x->w_dirhold)
		hm2_write_now(hm2, hm2_md_addr(s->md, REG_DIRHOLD, i), &v, 4);
	x->w_dirhold = v;

	if (type > 16) {
		HM2_ERR(hm2, "stepgen.%02d: step_type %u is not 0..16; using 0 (step/dir)", i, type);
		x->step_type = type = 0;
	}
	mode = type <= 2 ? type : 3;
	if (x->swap_step_dir)
		mode |= 1u << 2;
	sum = type > 2 ? (x->table_data[0] ^ x->table_data[1] * 3 ^ x->table_data[2] * 5 ^
			  x->table_data[3] * 7 ^ type) : 0;
	if (type > 2 && (x->force || sum != x->w_table_sum || mode != x->w_mode)) {
		/* the table is written from the last step to the first, then its length - 1 */
		for (j = (int)type - 1; j >= 0; j--) {
			v = (x->table_data[j / 4] >> (8 * (j % 4))) & 0xFF;
			hm2_write_now(hm2, hm2_md_addr(s->md, REG_TABLE, i), &v, 4);
		}
		v = type - 1;
		hm2_write_now(hm2, hm2_md_addr(s->md, REG_TABLELEN, i), &v, 4);
	}
	x->w_table_sum = sum;
	if (x->force || mode != x->w_mode)
		hm2_write_now(hm2, hm2_md_addr(s->md, REG_MODE, i), &mode, 4);
	x->w_mode = mode;
	x->force = 0;
}

void hm2_stepgen_write(struct hostmot2 *hm2)
{
	struct hm2_stepgen *s = &hm2->stepgen;
	int i;

	for (i = 0; i < s->num; i++)
		write_inst(hm2, i);
	if (s->has_timer && s->timer_number != s->written_timer) {
		int t = s->timer_number;
		rtapi_u32 v = (t >= 0 && t <= 4) ? (0x8000u | ((rtapi_u32)t << 12)) : 0;

		hm2_write_now(hm2, hm2_md_addr(s->md, REG_TIMER, 0), &v, 4);
		s->written_timer = t;
	}
}

void hm2_stepgen_force_write(struct hostmot2 *hm2)
{
	struct hm2_stepgen *s = &hm2->stepgen;
	rtapi_u32 dds = 0xFFFFFFFFu;
	int i;

	if (!s->num)
		return;
	hm2_write_now(hm2, hm2_md_addr(s->md, REG_MASTERDDS, 0), &dds, 4);
	for (i = 0; i < s->num; i++)
		s->inst[i].force = 1;
	s->written_timer = s->timer_number + 1;	/* forces the timer select too */
	hm2_stepgen_write(hm2);
}

/* After the load-time read: feedback starts at 0 from the current accumulator. */
void hm2_stepgen_prepare(struct hostmot2 *hm2)
{
	int i;

	for (i = 0; i < hm2->stepgen.num; i++)
		hm2->stepgen.inst[i].prev_acc = hm2->stepgen.acc_rd[i];
}
