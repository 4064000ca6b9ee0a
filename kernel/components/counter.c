/* SPDX-License-Identifier: GPL-2.0-or-later */
/* counter.c - counts input pulses, counter(9) (deprecated: encoder with
 * counter-mode TRUE does the same): loadrt counter [num_chan=N].
 * One channel by default, at most 8. Per channel counter.N:
 *   pins phase-A phase-Z (bit in), index-enable reset (bit io), counts (s32 out),
 *   position velocity (float out); params position-scale (float rw, default 1.0),
 *   rawcounts (s32 ro).
 * Functions counter.update-counters (no FP) and counter.capture-position (FP).
 * Counting is encoder_core.h in counter mode; the velocity reads 0 below one
 * count per second (counter has no min-speed-estimate). As LinuxCNC's counter does,
 * the inputs start out low (phase-A high in the first period is a count) and an
 * index pulse is taken when index-enable was TRUE at the last capture-position. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "encoder_core.h"
#include "counter_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("pulse counter (deprecated, use encoder counter-mode)");

static int num_chan = 1;
RTAPI_MP_INT(num_chan, "number of counters, 1..8");

static int comp_id;

static void counter_update_counters(void *arg, long period_ns)
{
	struct counter_set *set = arg;
	struct enc_update_in in = { .counter_mode = true, .x4_mode = true };
	int i;

	for (i = 0; i < set->num; i++) {
		struct counter_chan *c = &set->chan[i];

		in.a = *c->phase_a;
		in.z = *c->phase_z;
		in.index_enable = c->index_armed;
		c->rawcounts = enc_update(&c->up, &c->shared, &c->acks, &in, period_ns);
	}
}

static int counter_export(struct counter_chan *c, int n)
{
	int err;

	err = hal_pin_bit_newf(HAL_IN, &c->phase_a, comp_id, "counter.%d.phase-A", n);
	if (!err)
		err = hal_pin_bit_newf(HAL_IN, &c->phase_z, comp_id, "counter.%d.phase-Z", n);
	if (!err)
		err = hal_pin_bit_newf(HAL_IO, &c->index_enable, comp_id, "counter.%d.index-enable",
				       n);
	if (!err)
		err = hal_pin_bit_newf(HAL_IO, &c->reset, comp_id, "counter.%d.reset", n);
	if (!err)
		err = hal_pin_s32_newf(HAL_OUT, &c->counts, comp_id, "counter.%d.counts", n);
	if (!err)
		err = hal_pin_float_newf(HAL_OUT, &c->position, comp_id, "counter.%d.position", n);
	if (!err)
		err = hal_pin_float_newf(HAL_OUT, &c->velocity, comp_id, "counter.%d.velocity", n);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &c->scale, comp_id, "counter.%d.position-scale",
					   n);
	if (!err)
		err = hal_param_s32_newf(HAL_RO, &c->rawcounts, comp_id, "counter.%d.rawcounts", n);
	if (err)
		return err;
	*(volatile rtapi_u64 *)&c->scale = FLOAT_ONE_BITS;
	c->up.primed = true;	/* with low previous levels: the first period can count */
	c->up.a = c->up.z = false;
	c->up.pos = enc_quad_pos(false, false);
	c->index_armed = false;
	return 0;
}

int rtapi_app_main(void)
{
	struct counter_set *set;
	int n, err;

	if (num_chan < 1 || num_chan > COUNTER_MAX) {
		rtapi_print_msg(RTAPI_MSG_ERR, "counter: num_chan=%d is out of range, must be 1..%d\n",
				num_chan, COUNTER_MAX);
		return -EINVAL;
	}
	comp_id = hal_init("counter");
	if (comp_id < 0)
		return comp_id;
	set = hal_malloc((long)sizeof(*set) + num_chan * (long)sizeof(set->chan[0]));
	err = set ? 0 : -ENOMEM;
	if (!set)
		rtapi_print_msg(RTAPI_MSG_ERR, "counter: out of HAL memory for %d channels\n",
				num_chan);
	else
		set->num = num_chan;
	for (n = 0; !err && n < num_chan; n++)
		err = counter_export(&set->chan[n], n);
	if (!err)
		err = hal_export_funct("counter.update-counters", counter_update_counters, set, 0, 0,
				       comp_id);
	if (!err)
		err = hal_export_funct("counter.capture-position", counter_capture_position, set, 1,
				       0, comp_id);
	if (err) {
		hal_exit(comp_id);	/* removes every pin, parameter and function made so far */
		return err;
	}
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
