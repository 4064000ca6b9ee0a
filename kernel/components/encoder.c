/* SPDX-License-Identifier: GPL-2.0-or-later */
/* encoder.c - software counting of quadrature encoder signals, encoder(9) and the
 * Encoder section of the realtime components chapter:
 *   loadrt encoder [num_chan=num | names=name1[,name2...]]
 * Three channels by default, at most 8. Per channel PREFIX (encoder.N or the name):
 *   in:  phase-A phase-B phase-Z reset latch-input latch-rising latch-falling (bit),
 *        missing-teeth (s32), min-speed-estimate (float, default 1.0)
 *   i/o: index-enable counter-mode x4-mode (bit), position-scale (float, default 1.0)
 *   out: counts counts-latched rawcounts (s32), position position-interpolated
 *        position-latched velocity (float)
 * Functions (every channel at once): encoder.update-counters (no FP) and
 * encoder.capture-position (FP). The counting and estimating is encoder_core.h. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "comp_setup.h"
#include "instance_names.h"
#include "encoder_core.h"
#include "encoder_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("software quadrature encoder counter");

static int num_chan = -1;	/* -1: not given */
RTAPI_MP_INT(num_chan, "number of encoder channels, 1..8 (default 3)");
static char *names[ENCODER_MAX];
RTAPI_MP_ARRAY_STRING(names, ENCODER_MAX, "names of the encoder channels (instead of num_chan)");

static int comp_id;

static void encoder_update_counters(void *arg, long period_ns)
{
	struct encoder_set *set = arg;
	struct enc_update_in in;
	int i;

	for (i = 0; i < set->num; i++) {
		struct encoder_chan *e = &set->chan[i];

		in.a = *e->phase_a;
		in.b = *e->phase_b;
		in.z = *e->phase_z;
		in.index_enable = *e->index_enable;
		in.latch_input = *e->latch_input;
		in.latch_rising = *e->latch_rising;
		in.latch_falling = *e->latch_falling;
		in.counter_mode = *e->counter_mode;
		in.x4_mode = *e->x4_mode;
		in.missing_teeth = *e->missing_teeth;
		*e->rawcounts = enc_update(&e->up, &e->shared, &e->acks, &in, period_ns);
	}
}

static int bit_pin(hal_pin_dir_t dir, hal_bit_t **p, const char *prefix, const char *name)
{
	return hal_pin_bit_newf(dir, p, comp_id, "%s.%s", prefix, name);
}

static int s32_pin(hal_pin_dir_t dir, hal_s32_t **p, const char *prefix, const char *name)
{
	return hal_pin_s32_newf(dir, p, comp_id, "%s.%s", prefix, name);
}

static int float_pin(hal_pin_dir_t dir, hal_float_t **p, const char *prefix, const char *name)
{
	return hal_pin_float_newf(dir, p, comp_id, "%s.%s", prefix, name);
}

static int encoder_export(struct encoder_chan *e, const char *prefix)
{
	int err;

	err = bit_pin(HAL_IN, &e->phase_a, prefix, "phase-A");
	if (!err)
		err = bit_pin(HAL_IN, &e->phase_b, prefix, "phase-B");
	if (!err)
		err = bit_pin(HAL_IN, &e->phase_z, prefix, "phase-Z");
	if (!err)
		err = bit_pin(HAL_IO, &e->index_enable, prefix, "index-enable");
	if (!err)
		err = bit_pin(HAL_IN, &e->reset, prefix, "reset");
	if (!err)
		err = bit_pin(HAL_IN, &e->latch_input, prefix, "latch-input");
	if (!err)
		err = bit_pin(HAL_IN, &e->latch_rising, prefix, "latch-rising");
	if (!err)
		err = bit_pin(HAL_IN, &e->latch_falling, prefix, "latch-falling");
	if (!err)
		err = bit_pin(HAL_IO, &e->counter_mode, prefix, "counter-mode");
	if (!err)
		err = bit_pin(HAL_IO, &e->x4_mode, prefix, "x4-mode");
	if (!err)
		err = s32_pin(HAL_IN, &e->missing_teeth, prefix, "missing-teeth");
	if (!err)
		err = s32_pin(HAL_OUT, &e->counts, prefix, "counts");
	if (!err)
		err = s32_pin(HAL_OUT, &e->counts_latched, prefix, "counts-latched");
	if (!err)
		err = s32_pin(HAL_OUT, &e->rawcounts, prefix, "rawcounts");
	if (!err)
		err = float_pin(HAL_OUT, &e->position, prefix, "position");
	if (!err)
		err = float_pin(HAL_OUT, &e->position_interpolated, prefix, "position-interpolated");
	if (!err)
		err = float_pin(HAL_OUT, &e->position_latched, prefix, "position-latched");
	if (!err)
		err = float_pin(HAL_OUT, &e->velocity, prefix, "velocity");
	if (!err)
		err = float_pin(HAL_IO, &e->scale, prefix, "position-scale");
	if (!err)
		err = float_pin(HAL_IN, &e->min_speed, prefix, "min-speed-estimate");
	if (err)
		return err;
	*e->latch_rising = true;
	*e->latch_falling = true;
	*e->x4_mode = true;
	*(volatile rtapi_u64 *)e->scale = FLOAT_ONE_BITS;
	*(volatile rtapi_u64 *)e->min_speed = FLOAT_ONE_BITS;
	return 0;
}

int rtapi_app_main(void)
{
	char prefix[HAL_NAME_LEN + 1];
	struct encoder_set *set;
	int n, i, err;

	if (num_chan <= 0 && (!names[0] || !names[0][0]))	/* num_chan=0: the default */
		num_chan = ENCODER_DEFAULT;
	n = instance_count("encoder", "num_chan", num_chan, names, ENCODER_MAX, ENCODER_MAX);
	if (n < 0)
		return n;
	set = comp_setup("encoder", (long)sizeof(*set) + n * (long)sizeof(set->chan[0]), &comp_id, &err);
	if (!set)
		return err;
	set->num = n;
	for (i = 0; !err && i < n; i++) {
		instance_prefix(prefix, sizeof(prefix), "encoder", names, i);
		err = encoder_export(&set->chan[i], prefix);
	}
	if (!err)
		err = hal_export_funct("encoder.update-counters", encoder_update_counters, set, 0, 0,
				       comp_id);
	if (!err)
		err = hal_export_funct("encoder.capture-position", encoder_capture_position, set, 1,
				       0, comp_id);
	return comp_finish(comp_id, err);
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
