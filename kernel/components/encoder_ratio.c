/* SPDX-License-Identifier: GPL-2.0-or-later */
/* encoder_ratio.c - an electronic gear to synchronize two axes, encoder_ratio(9):
 *   loadrt encoder_ratio [num_chan=num | names=name1[,name2...]]
 * One pair by default, at most 8. Per pair PREFIX (encoder-ratio.N or the name):
 * pins master-A master-B slave-A slave-B enable (bit in), error (float out);
 * params master-ppr slave-ppr master-teeth slave-teeth (u32 rw; ppr default 100,
 * teeth default 1). Functions (every pair at once) encoder-ratio.sample (no FP)
 * and encoder-ratio.update (FP). The gear is encoder_ratio_core.h. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "comp_setup.h"
#include "instance_names.h"
#include "encoder_ratio_core.h"
#include "encoder_ratio_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("electronic gear between two encoders");

static int num_chan = -1;	/* -1: not given (one pair, unless names= is) */
RTAPI_MP_INT(num_chan, "number of axis pairs, 1..8");
static char *names[ENCODER_RATIO_MAX];
RTAPI_MP_ARRAY_STRING(names, ENCODER_RATIO_MAX, "names of the axis pairs (instead of num_chan)");

static int comp_id;

static void encoder_ratio_sample(void *arg, long period_ns)
{
	struct encoder_ratio_set *set = arg;
	int i;

	for (i = 0; i < set->num; i++) {
		struct encoder_ratio_chan *c = &set->chan[i];

		enc_ratio_sample(&c->st, &c->counts, *c->master_a, *c->master_b, *c->slave_a,
				 *c->slave_b, *c->enable);
	}
}

static int bit_in(hal_bit_t **p, const char *prefix, const char *name)
{
	return hal_pin_bit_newf(HAL_IN, p, comp_id, "%s.%s", prefix, name);
}

static int u32_param(hal_u32_t *p, const char *prefix, const char *name)
{
	return hal_param_u32_newf(HAL_RW, p, comp_id, "%s.%s", prefix, name);
}

static int encoder_ratio_export(struct encoder_ratio_chan *c, const char *prefix)
{
	int err;

	err = bit_in(&c->master_a, prefix, "master-A");
	if (!err)
		err = bit_in(&c->master_b, prefix, "master-B");
	if (!err)
		err = bit_in(&c->slave_a, prefix, "slave-A");
	if (!err)
		err = bit_in(&c->slave_b, prefix, "slave-B");
	if (!err)
		err = bit_in(&c->enable, prefix, "enable");
	if (!err)
		err = hal_pin_float_newf(HAL_OUT, &c->error, comp_id, "%s.error", prefix);
	if (!err)
		err = u32_param(&c->master_ppr, prefix, "master-ppr");
	if (!err)
		err = u32_param(&c->slave_ppr, prefix, "slave-ppr");
	if (!err)
		err = u32_param(&c->master_teeth, prefix, "master-teeth");
	if (!err)
		err = u32_param(&c->slave_teeth, prefix, "slave-teeth");
	if (err)
		return err;
	c->master_ppr = c->slave_ppr = 100;
	c->master_teeth = c->slave_teeth = 1;
	return 0;
}

int rtapi_app_main(void)
{
	char prefix[HAL_NAME_LEN + 1];
	struct encoder_ratio_set *set;
	int n, i, err;

	n = instance_count("encoder_ratio", "num_chan", num_chan, names, ENCODER_RATIO_MAX,
			   ENCODER_RATIO_MAX);
	if (n < 0)
		return n;
	set = comp_setup("encoder_ratio", (long)sizeof(*set) + n * (long)sizeof(set->chan[0]), &comp_id, &err);
	if (!set)
		return err;
	set->num = n;
	for (i = 0; !err && i < n; i++) {
		instance_prefix(prefix, sizeof(prefix), "encoder-ratio", names, i);
		err = encoder_ratio_export(&set->chan[i], prefix);
	}
	if (!err)
		err = hal_export_funct("encoder-ratio.sample", encoder_ratio_sample, set, 0, 0,
				       comp_id);
	if (!err)
		err = hal_export_funct("encoder-ratio.update", encoder_ratio_update, set, 1, 0,
				       comp_id);
	return comp_finish(comp_id, err);
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
