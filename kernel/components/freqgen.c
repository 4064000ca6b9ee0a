/* SPDX-License-Identifier: GPL-2.0-or-later */
/* freqgen.c - software step pulse generation by velocity, freqgen(9) (obsolete:
 * stepgen ctrl_type=v replaces it; kept for old configurations):
 *   loadrt freqgen [step_type=T0[,T1...]]   (types 0-14, up to 8; default 0,0,0)
 * As its page documents, unlike stepgen: the command pin is "velocity" (scaled
 * by velocity-scale), maxfreq and maxaccel are in steps, steplen/stepspace/
 * dirsetup/dirhold are in make-pulses periods (type 0 only), there is no enable
 * pin, and type 1 pulses are one period long. Shares stepgen_core.h/_loop.h. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "comp_setup.h"
#include "stepgen_core.h"
#include "stepgen_loop.h"
#include "freqgen_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("software step pulse generation by velocity (obsolete)");

static int step_type[STEPGEN_MAX_CHAN] = { -1, -1, -1, -1, -1, -1, -1, -1 };
RTAPI_MP_ARRAY_INT(step_type, STEPGEN_MAX_CHAN, "step type of each generator, 0..14");

static int comp_id;

static void make_pulses(void *arg, long period_ns)
{
	struct freqgen_comp *c = arg;
	int n, i;

	c->base_period_ns = (rtapi_u32)period_ns;
	for (n = 0; n < c->num_chan; n++) {
		struct freqgen_chan *ch = &c->chan[n];

		stepgen_pulse_step(&ch->pulse, ch->type,
				   &stepgen_builtin_patterns[ch->type < 2 ? 2 : ch->type],
				   &ch->timing, true);
		ch->rawcounts = ch->pulse.rawcount;
		for (i = 0; i < ch->num_out; i++)
			*ch->out[i] = ch->pulse.out[i];
	}
}

static const char *const out_names[3][STEPGEN_MAX_PHASES] = {
	{ "step", "dir" },
	{ "up", "down" },
	{ "phase-A", "phase-B", "phase-C", "phase-D", "phase-E" },
};

static int float_param(hal_float_t *p, int n, const char *name)
{
	return hal_param_float_newf(HAL_RW, p, comp_id, "freqgen.%d.%s", n, name);
}

static int export_chan(struct freqgen_chan *ch, int n)
{
	const char *const *names = out_names[ch->type < 2 ? ch->type : 2];
	int i, err;

	err = hal_pin_float_newf(HAL_IN, &ch->velocity, comp_id, "freqgen.%d.velocity", n);
	if (!err)
		err = hal_pin_s32_newf(HAL_OUT, &ch->counts, comp_id, "freqgen.%d.counts", n);
	if (!err)
		err = hal_pin_float_newf(HAL_OUT, &ch->position_fb, comp_id,
					 "freqgen.%d.position-fb", n);
	for (i = 0; !err && i < ch->num_out; i++)
		err = hal_pin_bit_newf(HAL_OUT, &ch->out[i], comp_id, "freqgen.%d.%s", n, names[i]);
	if (!err)
		err = hal_param_float_newf(HAL_RO, &ch->frequency, comp_id, "freqgen.%d.frequency", n);
	if (!err)
		err = float_param(&ch->maxaccel, n, "maxaccel");
	if (!err)
		err = float_param(&ch->maxfreq, n, "maxfreq");
	if (!err)
		err = float_param(&ch->position_scale, n, "position-scale");
	if (!err)
		err = float_param(&ch->velocity_scale, n, "velocity-scale");
	if (!err)
		err = hal_param_s32_newf(HAL_RO, &ch->rawcounts, comp_id, "freqgen.%d.rawcounts", n);
	if (!err && ch->type == 0)
		err = hal_param_u32_newf(HAL_RW, &ch->steplen, comp_id, "freqgen.%d.steplen", n);
	if (!err && ch->type == 0)
		err = hal_param_u32_newf(HAL_RW, &ch->stepspace, comp_id, "freqgen.%d.stepspace", n);
	if (!err && ch->type == 0)
		err = hal_param_u32_newf(HAL_RW, &ch->dirsetup, comp_id, "freqgen.%d.dirsetup", n);
	if (!err && ch->type == 0)
		err = hal_param_u32_newf(HAL_RW, &ch->dirhold, comp_id, "freqgen.%d.dirhold", n);
	return err;
}

int rtapi_app_main(void)
{
	int types[STEPGEN_MAX_CHAN] = { 0, 0, 0 };
	struct freqgen_comp *c;
	int num, n, err;

	for (num = 0; num < STEPGEN_MAX_CHAN && step_type[num] != -1; num++) {
		if (step_type[num] < 0 || step_type[num] > 14) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"freqgen: step_type= entry %d is %d, must be 0..14\n",
					num + 1, step_type[num]);
			return -EINVAL;
		}
		types[num] = step_type[num];
	}
	if (num == 0)
		num = 3;	/* like stepgen: three step/dir generators */
	c = comp_setup("freqgen", sizeof(*c), &comp_id, &err);
	if (!c)
		return err;
	c->num_chan = num;
	for (n = 0; !err && n < num; n++) {
		struct freqgen_chan *ch = &c->chan[n];

		ch->type = types[n];
		ch->num_out = ch->type < 2 ? 2 : stepgen_builtin_patterns[ch->type].phases;
		/* type 1 and the state types: one-period steps, immediate reversal */
		ch->timing = (struct stepgen_timing){ 1, ch->type == 1 ? 1 : 0, 0, 0, 0 };
		stepgen_pulse_init(&ch->pulse);
		err = export_chan(ch, n);
		ch->steplen = ch->stepspace = ch->dirsetup = ch->dirhold = 1;
		*(volatile rtapi_u64 *)&ch->position_scale = FLOAT_ONE_BITS;
		*(volatile rtapi_u64 *)&ch->velocity_scale = FLOAT_ONE_BITS;
	}
	if (!err)
		err = hal_export_funct("freqgen.make-pulses", make_pulses, c, 0, 0, comp_id);
	if (!err)
		err = hal_export_funct("freqgen.update-freq", update_freq, c, 1, 0, comp_id);
	if (!err)
		err = hal_export_funct("freqgen.capture-position", capture_position, c, 1, 0, comp_id);
	return comp_finish(comp_id, err);
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
