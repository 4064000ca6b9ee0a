/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sim_encoder.c - simulated quadrature encoder, sim_encoder(9) and the Simulated
 * Encoder section: loadrt sim_encoder [num_chan=num | names=name1[,name2...]].
 * One channel by default, at most 8. Per channel PREFIX (sim-encoder.N, RULINGS.md,
 * or the name): pins phase-A phase-B phase-Z (bit out), speed (float in); params
 * ppr (u32, default 100), scale (float, default 1.0). Functions (every channel at
 * once) sim-encoder.make-pulses (no FP) and sim-encoder.update-speed (FP).
 * The pulse generation is sim_encoder_core.h. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "comp_setup.h"
#include "instance_names.h"
#include "sim_encoder_core.h"
#include "sim_encoder_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("simulated quadrature encoder");

static int num_chan = -1;	/* -1: not given (one channel, unless names= is) */
RTAPI_MP_INT(num_chan, "number of simulated encoders, 1..8");
static char *names[SIM_ENCODER_MAX];
RTAPI_MP_ARRAY_STRING(names, SIM_ENCODER_MAX, "names of the simulated encoders (instead of num_chan)");

static int comp_id;

static void sim_encoder_make_pulses(void *arg, long period_ns)
{
	struct sim_encoder_set *set = arg;
	struct sim_enc_out o;
	int i;

	for (i = 0; i < set->num; i++) {
		struct sim_encoder_chan *c = &set->chan[i];

		sim_enc_make_pulses(&c->st, &c->shared, period_ns, &o);
		*c->phase_a = o.a;
		*c->phase_b = o.b;
		*c->phase_z = o.z;
	}
}

static int sim_encoder_export(struct sim_encoder_chan *c, const char *prefix)
{
	int err;

	err = hal_pin_bit_newf(HAL_OUT, &c->phase_a, comp_id, "%s.phase-A", prefix);
	if (!err)
		err = hal_pin_bit_newf(HAL_OUT, &c->phase_b, comp_id, "%s.phase-B", prefix);
	if (!err)
		err = hal_pin_bit_newf(HAL_OUT, &c->phase_z, comp_id, "%s.phase-Z", prefix);
	if (!err)
		err = hal_pin_float_newf(HAL_IN, &c->speed, comp_id, "%s.speed", prefix);
	if (!err)
		err = hal_param_u32_newf(HAL_RW, &c->ppr, comp_id, "%s.ppr", prefix);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &c->scale, comp_id, "%s.scale", prefix);
	if (err)
		return err;
	c->ppr = 100;
	*(volatile rtapi_u64 *)&c->scale = FLOAT_ONE_BITS;
	return 0;
}

int rtapi_app_main(void)
{
	char prefix[HAL_NAME_LEN + 1];
	struct sim_encoder_set *set;
	int n, i, err;

	n = instance_count("sim_encoder", "num_chan", num_chan, names, SIM_ENCODER_MAX,
			   SIM_ENCODER_MAX);
	if (n < 0)
		return n;
	set = comp_setup("sim_encoder", (long)sizeof(*set) + n * (long)sizeof(set->chan[0]), &comp_id, &err);
	if (!set)
		return err;
	set->num = n;
	for (i = 0; !err && i < n; i++) {
		instance_prefix(prefix, sizeof(prefix), "sim-encoder", names, i);
		err = sim_encoder_export(&set->chan[i], prefix);
	}
	if (!err)
		err = hal_export_funct("sim-encoder.make-pulses", sim_encoder_make_pulses, set, 0, 0,
				       comp_id);
	if (!err)
		err = hal_export_funct("sim-encoder.update-speed", sim_encoder_update_speed, set, 1,
				       0, comp_id);
	return comp_finish(comp_id, err);
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
