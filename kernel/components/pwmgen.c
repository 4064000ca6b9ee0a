/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pwmgen.c - software PWM/PDM generation, pwmgen(9) and the PWMgen section of the
 * realtime components chapter: loadrt pwmgen output_type=T0[,T1...] (required,
 * up to 8; 0 PWM only, 1 PWM + dir, 2 up/down). Functions pwmgen.make-pulses
 * (no FP) and pwmgen.update (FP), each for all channels. Logic: pwmgen_core.h. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "comp_setup.h"
#include "pwmgen_core.h"
#include "pwmgen_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("software PWM/PDM generation");

static int output_type[PWMGEN_MAX_CHAN] = { -1, -1, -1, -1, -1, -1, -1, -1 };
RTAPI_MP_ARRAY_INT(output_type, PWMGEN_MAX_CHAN, "output type of each generator, 0..2");

static int comp_id;

static void make_pulses(void *arg, long period_ns)
{
	struct pwmgen_comp *c = arg;
	int n;

	c->base_period_ns = (rtapi_u32)period_ns;
	for (n = 0; n < c->num_chan; n++) {
		struct pwmgen_chan *ch = &c->chan[n];
		bool on = pwmgen_pulse_step(&ch->pulse, &ch->plan);
		bool rev = ch->plan.enabled && ch->plan.reverse;

		if (ch->type == 2) {
			*ch->out[0] = on && !rev;	/* up */
			*ch->out[1] = on && rev;	/* down */
		} else {
			*ch->out[0] = on;
			if (ch->type == 1)
				*ch->out[1] = rev;	/* dir: high for negative */
		}
	}
}

static const char *const out_names[3][2] = { { "pwm", NULL }, { "pwm", "dir" }, { "up", "down" } };

static int export_chan(struct pwmgen_chan *ch, int n)
{
	int i, err;

	err = hal_pin_float_newf(HAL_IN, &ch->value, comp_id, "pwmgen.%d.value", n);
	if (!err)
		err = hal_pin_bit_newf(HAL_IN, &ch->enable, comp_id, "pwmgen.%d.enable", n);
	for (i = 0; !err && i < 2 && out_names[ch->type][i]; i++)
		err = hal_pin_bit_newf(HAL_OUT, &ch->out[i], comp_id, "pwmgen.%d.%s", n,
				       out_names[ch->type][i]);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &ch->scale, comp_id, "pwmgen.%d.scale", n);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &ch->offset, comp_id, "pwmgen.%d.offset", n);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &ch->pwm_freq, comp_id, "pwmgen.%d.pwm-freq", n);
	if (!err)
		err = hal_param_bit_newf(HAL_RW, &ch->dither, comp_id, "pwmgen.%d.dither-pwm", n);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &ch->min_dc, comp_id, "pwmgen.%d.min-dc", n);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &ch->max_dc, comp_id, "pwmgen.%d.max-dc", n);
	if (!err)
		err = hal_param_float_newf(HAL_RO, &ch->curr_dc, comp_id, "pwmgen.%d.curr-dc", n);
	return err;
}

/* Defaults as bit patterns: kernel init code runs outside FPU sections. */

int rtapi_app_main(void)
{
	struct pwmgen_comp *c;
	int num, n, err;

	for (num = 0; num < PWMGEN_MAX_CHAN && output_type[num] != -1; num++) {
		if (output_type[num] < 0 || output_type[num] > 2) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"pwmgen: output_type= entry %d is %d, must be 0, 1 or 2\n",
					num + 1, output_type[num]);
			return -EINVAL;
		}
	}
	if (num == 0) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"pwmgen: no output_type= given; e.g. output_type=0,1,2 makes three generators\n");
		return -EINVAL;
	}
	c = comp_setup("pwmgen", sizeof(*c), &comp_id, &err);
	if (!c)
		return err;
	c->num_chan = num;
	for (n = 0; !err && n < num; n++) {
		c->chan[n].type = output_type[n];
		err = export_chan(&c->chan[n], n);
		*(volatile rtapi_u64 *)&c->chan[n].scale = FLOAT_ONE_BITS;
		*(volatile rtapi_u64 *)&c->chan[n].max_dc = FLOAT_ONE_BITS;
	}
	if (!err)
		err = hal_export_funct("pwmgen.make-pulses", make_pulses, c, 0, 0, comp_id);
	if (!err)
		err = hal_export_funct("pwmgen.update", update, c, 1, 0, comp_id);
	return comp_finish(comp_id, err);
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
