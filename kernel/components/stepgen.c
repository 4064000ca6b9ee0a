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

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("software step pulse generation");

static int step_type[STEPGEN_MAX_CHAN] = { -1, -1, -1, -1, -1, -1, -1, -1 };
RTAPI_MP_ARRAY_INT(step_type, STEPGEN_MAX_CHAN, "step type of each generator, 0..15");
static char *ctrl_type[STEPGEN_MAX_CHAN];
RTAPI_MP_ARRAY_STRING(ctrl_type, STEPGEN_MAX_CHAN, "p (position) or v (velocity) per generator");
static int user_step_type[STEPGEN_MAX_CYCLE] = { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 };
RTAPI_MP_ARRAY_INT(user_step_type, STEPGEN_MAX_CYCLE,
		   "phase bits of each state of step type 15, up to 10 states of 5 phases");

struct stepgen_chan {		/* in hal_malloc() memory */
	int type;		/* step type, fixed at load */
	bool velocity_mode;	/* ctrl_type v */
	const struct stepgen_pattern *pat;	/* types 2-15 */
	hal_float_t *cmd;	/* position-cmd or velocity-cmd: read by update-freq */
	hal_bit_t *enable;	/* read by make-pulses and update-freq */
	hal_s32_t *counts;	/* written by capture-position */
	hal_float_t *position_fb;	/* written by capture-position */
	hal_bit_t *out[STEPGEN_MAX_PHASES];	/* step/dir, up/down or phase-A..E */
	int num_out;
	hal_float_t position_scale, maxvel, maxaccel;	/* RW params, read by update-freq */
	hal_float_t frequency;	/* RO param: written by update-freq */
	hal_u32_t steplen, stepspace, dirsetup, dirhold, dirdelay;	/* ns, RW */
	hal_s32_t rawcounts;	/* RO param: written by make-pulses */
	struct stepgen_timing timing;	/* periods: written by update-freq */
	struct stepgen_pulse pulse;	/* make-pulses (addval: update-freq) */
	struct stepgen_loop loop;	/* update-freq */
};

struct stepgen_comp {
	hal_u32_t base_period_ns;	/* make-pulses period: written by make-pulses */
	int num_chan;
	struct stepgen_pattern user_pat;	/* type 15 */
	struct stepgen_chan chan[STEPGEN_MAX_CHAN];
};

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

/* Position-scale 0 (or NaN) would divide by zero: use 1.0, as the default. */
static double usable_scale(struct stepgen_chan *ch)
{
	double s = ch->position_scale;

	if (!(fabs(s) > 1e-20)) {
		ch->position_scale = 1.0;
		s = 1.0;
	}
	return s;
}

static void update_timing(struct stepgen_chan *ch, rtapi_u32 base_ns)
{
	struct stepgen_timing *t = &ch->timing;

	t->steplen = stepgen_ns_to_periods(ch->steplen, base_ns);
	if (t->steplen == 0)
		t->steplen = 1;		/* a step pin must be high for at least one period */
	t->stepspace = stepgen_ns_to_periods(ch->stepspace, base_ns);
	t->dirsetup = stepgen_ns_to_periods(ch->dirsetup, base_ns);
	t->dirhold = stepgen_ns_to_periods(ch->dirhold, base_ns);
	t->dirdelay = stepgen_ns_to_periods(ch->dirdelay, base_ns);
}

static void update_freq(void *arg, long period_ns)
{
	struct stepgen_comp *c = arg;
	rtapi_u32 base_ns = c->base_period_ns;
	double t = period_ns * 1e-9;
	int n;

	for (n = 0; n < c->num_chan; n++) {
		struct stepgen_chan *ch = &c->chan[n];
		double scale = usable_scale(ch);
		double vlimit, vmax, amax, pos, v;
		rtapi_s64 addval;

		if (base_ns == 0 || !*ch->enable) {	/* make-pulses has not run yet, or off */
			rtapi_store_u64(&ch->pulse.addval, 0);
			ch->loop.vel = 0.0;
			ch->loop.has_old = false;
			ch->frequency = 0.0;
			continue;
		}
		update_timing(ch, base_ns);
		vlimit = stepgen_max_freq(ch->type, &ch->timing, base_ns) / fabs(scale);
		if (!(ch->maxvel >= 0.0))
			ch->maxvel = 0.0;
		if (ch->maxvel > vlimit)
			ch->maxvel = vlimit;	/* "reset to the highest attainable value" */
		vmax = ch->maxvel > 0.0 ? ch->maxvel : vlimit;
		if (!(ch->maxaccel >= 0.0))
			ch->maxaccel = 0.0;
		amax = ch->maxaccel;
		if (ch->velocity_mode) {
			v = stepgen_velocity_loop(&ch->loop, *ch->cmd, vmax, amax, t);
		} else {
			pos = stepgen_accum_to_steps(rtapi_load_u64(&ch->pulse.accum)) / scale;
			v = stepgen_position_loop(&ch->loop, *ch->cmd, pos, vmax, amax, t);
		}
		addval = stepgen_freq_to_addval(v * scale, base_ns);
		rtapi_store_u64(&ch->pulse.addval, (rtapi_u64)addval);
		ch->frequency = stepgen_addval_to_freq(addval, base_ns);
		ch->loop.vel = ch->frequency / scale;	/* what is really output */
	}
}

static void capture_position(void *arg, long period_ns)
{
	struct stepgen_comp *c = arg;
	int n;

	for (n = 0; n < c->num_chan; n++) {
		struct stepgen_chan *ch = &c->chan[n];

		*ch->counts = ch->pulse.rawcount;
		*ch->position_fb = stepgen_accum_to_steps(rtapi_load_u64(&ch->pulse.accum)) /
				   usable_scale(ch);
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
#define FLOAT_ONE_BITS 0x3ff0000000000000ULL	/* 1.0 */

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
