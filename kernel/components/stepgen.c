/* SPDX-License-Identifier: GPL-2.0-or-later */
/* stepgen.c - software step pulse generation, stepgen(9) and the StepGen section
 * of the realtime components chapter:
 *   loadrt stepgen [step_type=T0[,T1...]] [ctrl_type=p|v[,...]] [user_step_type=#,#...]
 * Up to 8 generators (three of type 0 when step_type= is not given), types 0-14
 * built in and 15 from user_step_type=. Functions stepgen.make-pulses (no FP),
 * stepgen.update-freq and stepgen.capture-position (FP), each for all channels.
 * Logic: stepgen_core.h (pulses, integer) and stepgen_loop.h (control loops). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "comp_setup.h"
#include "stepgen_core.h"
#include "stepgen_loop.h"
#include "stepgen_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("software step pulse generation");

static int step_type[STEPGEN_MAX_CHAN] = { -1, -1, -1, -1, -1, -1, -1, -1 };
RTAPI_MP_ARRAY_INT(step_type, STEPGEN_MAX_CHAN, "step type of each generator, 0..15");
static char *ctrl_type[STEPGEN_MAX_CHAN];
RTAPI_MP_ARRAY_STRING(ctrl_type, STEPGEN_MAX_CHAN, "p (position) or v (velocity) per generator");
static int user_step_type[STEPGEN_MAX_CYCLE] = { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 };
RTAPI_MP_ARRAY_INT(user_step_type, STEPGEN_MAX_CYCLE,
		   "phase bits of each state of step type 15, up to 10 states of 5 phases");

static int comp_id;

static void make_pulses(void *arg, long period_ns)
{
	struct stepgen_comp *c = arg;
	int n, i;

	c->base_period_ns = (rtapi_u32)period_ns;
	for (n = 0; n < c->num_chan; n++) {
		struct stepgen_chan *ch = &c->chan[n];

		stepgen_pulse_step(&ch->pulse, ch->type, ch->pat, &ch->timing, *ch->enable);
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

static int export_chan(struct stepgen_comp *c, int n)
{
	struct stepgen_chan *ch = &c->chan[n];
	const char *const *names = out_names[ch->type < 2 ? ch->type : 2];
	int i, err;

	err = hal_pin_float_newf(HAL_IN, &ch->cmd, comp_id, "stepgen.%d.%s", n,
				 ch->velocity_mode ? "velocity-cmd" : "position-cmd");
	if (!err)
		err = hal_pin_bit_newf(HAL_IN, &ch->enable, comp_id, "stepgen.%d.enable", n);
	if (!err)
		err = hal_pin_s32_newf(HAL_OUT, &ch->counts, comp_id, "stepgen.%d.counts", n);
	if (!err)
		err = hal_pin_float_newf(HAL_OUT, &ch->position_fb, comp_id,
					 "stepgen.%d.position-fb", n);
	for (i = 0; !err && i < ch->num_out; i++)
		err = hal_pin_bit_newf(HAL_OUT, &ch->out[i], comp_id, "stepgen.%d.%s", n, names[i]);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &ch->position_scale, comp_id,
					   "stepgen.%d.position-scale", n);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &ch->maxvel, comp_id, "stepgen.%d.maxvel", n);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &ch->maxaccel, comp_id, "stepgen.%d.maxaccel", n);
	if (!err)
		err = hal_param_float_newf(HAL_RO, &ch->frequency, comp_id, "stepgen.%d.frequency", n);
	if (!err)
		err = hal_param_s32_newf(HAL_RO, &ch->rawcounts, comp_id, "stepgen.%d.rawcounts", n);
	/* "only those [timing parameters] which will be used are exported" */
	if (!err)
		err = hal_param_u32_newf(HAL_RW, &ch->steplen, comp_id, "stepgen.%d.steplen", n);
	if (!err && ch->type <= 1)
		err = hal_param_u32_newf(HAL_RW, &ch->stepspace, comp_id, "stepgen.%d.stepspace", n);
	if (!err && ch->type == 0)
		err = hal_param_u32_newf(HAL_RW, &ch->dirsetup, comp_id, "stepgen.%d.dirsetup", n);
	if (!err && ch->type == 0)
		err = hal_param_u32_newf(HAL_RW, &ch->dirhold, comp_id, "stepgen.%d.dirhold", n);
	if (!err && ch->type >= 1)
		err = hal_param_u32_newf(HAL_RW, &ch->dirdelay, comp_id, "stepgen.%d.dirdelay", n);
	return err;
}

/* Defaults without FP instructions: kernel init code runs outside FPU sections. */

static void init_chan(struct stepgen_comp *c, int n, int type, bool velocity_mode)
{
	struct stepgen_chan *ch = &c->chan[n];

	ch->type = type;
	ch->velocity_mode = velocity_mode;
	if (type == STEPGEN_USER_TYPE)
		ch->pat = &c->user_pat;
	else
		ch->pat = &stepgen_builtin_patterns[type < 2 ? 2 : type];
	ch->num_out = type < 2 ? 2 : ch->pat->phases;
	*(volatile rtapi_u64 *)&ch->position_scale = FLOAT_ONE_BITS;
	ch->steplen = ch->stepspace = ch->dirsetup = ch->dirhold = ch->dirdelay = 1;
	ch->timing = (struct stepgen_timing){ 1, 1, 1, 1, 1 };
	stepgen_pulse_init(&ch->pulse);
}

/* Validates the module parameters; fills types[] and vmode[]. Returns the
 * number of generators or -EINVAL after one message naming the parameter. */
static int parse_params(int *types, bool *vmode, struct stepgen_pattern *user_pat)
{
	int n, num, bad = 0, err;

	for (num = 0; num < STEPGEN_MAX_CHAN && step_type[num] != -1; num++)
		;
	if (num == 0) {
		num = 3;	/* no step_type=: three step/dir generators */
		types[0] = types[1] = types[2] = 0;
	}
	for (n = 0; n < STEPGEN_MAX_CHAN && step_type[n] != -1; n++) {
		if (step_type[n] < 0 || step_type[n] >= STEPGEN_NUM_TYPES) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"stepgen: step_type= entry %d is %d, must be 0..15\n",
					n + 1, step_type[n]);
			return -EINVAL;
		}
		types[n] = step_type[n];
	}
	for (n = 0; n < STEPGEN_MAX_CHAN && ctrl_type[n]; n++) {
		if (n >= num) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"stepgen: ctrl_type= gives %d entries for %d generators\n",
					n + 1, num);
			return -EINVAL;
		}
		if ((ctrl_type[n][0] != 'p' && ctrl_type[n][0] != 'v' &&
		     ctrl_type[n][0] != 'P' && ctrl_type[n][0] != 'V') || ctrl_type[n][1]) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"stepgen: ctrl_type= entry %d is '%s', must be p or v\n",
					n + 1, ctrl_type[n]);
			return -EINVAL;
		}
		vmode[n] = ctrl_type[n][0] == 'v' || ctrl_type[n][0] == 'V';
	}
	err = stepgen_user_pattern(user_step_type, STEPGEN_MAX_CYCLE, user_pat, &bad);
	if (err == -EINVAL) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"stepgen: user_step_type= entry %d is %d, uses more than 5 phases (must be 0..31)\n",
				bad + 1, user_step_type[bad]);
		return -EINVAL;
	}
	for (n = 0; n < num; n++) {
		if (types[n] == STEPGEN_USER_TYPE && err == -ENOENT) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"stepgen: step type 15 (generator %d) needs user_step_type=\n", n);
			return -EINVAL;
		}
	}
	return num;
}

int rtapi_app_main(void)
{
	int types[STEPGEN_MAX_CHAN] = { 0 };
	bool vmode[STEPGEN_MAX_CHAN] = { 0 };
	struct stepgen_pattern user_pat;
	struct stepgen_comp *c;
	int num, n, err;

	num = parse_params(types, vmode, &user_pat);
	if (num < 0)
		return num;
	c = comp_setup("stepgen", sizeof(*c), &comp_id, &err);
	if (!c)
		return err;
	if (c) {
		c->num_chan = num;
		c->user_pat = user_pat;
	}
	for (n = 0; !err && n < num; n++) {
		init_chan(c, n, types[n], vmode[n]);
		err = export_chan(c, n);
	}
	if (!err)
		err = hal_export_funct("stepgen.make-pulses", make_pulses, c, 0, 0, comp_id);
	if (!err)
		err = hal_export_funct("stepgen.update-freq", update_freq, c, 1, 0, comp_id);
	if (!err)
		err = hal_export_funct("stepgen.capture-position", capture_position, c, 1, 0, comp_id);
	return comp_finish(comp_id, err);
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
