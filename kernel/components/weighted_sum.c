/* SPDX-License-Identifier: GPL-2.0-or-later */
/* weighted_sum.c - convert a group of bits to an integer, weighted_sum(9):
 * loadrt weighted_sum wsum_sizes=size[,size...] (required; at most 8 summers of
 * 1..16 bits). Summer N: pins wsum.N.bit.M.in, wsum.N.hold (bit in), wsum.N.sum
 * (s32 out); params wsum.N.bit.M.weight (default 2^M) and wsum.N.offset (s32 RW);
 * one function process_wsums (no FP) for all summers. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "comp_setup.h"
#include "weighted_sum_core.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("weighted sum of bits");

#define WSUM_MAX_SUMMERS 8

static int wsum_sizes[WSUM_MAX_SUMMERS] = { -1, -1, -1, -1, -1, -1, -1, -1 };
RTAPI_MP_ARRAY_INT(wsum_sizes, WSUM_MAX_SUMMERS, "input bits of each weighted summer, 1..16");

struct wsum {			/* in hal_malloc() memory */
	int num_bits;
	hal_bit_t *in[WSUM_MAX_BITS];	/* read by process_wsums */
	hal_bit_t *hold;
	hal_s32_t *sum;		/* written by process_wsums */
	hal_s32_t weight[WSUM_MAX_BITS], offset;	/* RW params */
};

struct wsum_comp {
	int num;
	struct wsum w[WSUM_MAX_SUMMERS];
};

static int comp_id;

static void process_wsums(void *arg, long period_ns)
{
	struct wsum_comp *c = arg;
	bool bits[WSUM_MAX_BITS];
	rtapi_s32 weights[WSUM_MAX_BITS];
	int n, m;

	for (n = 0; n < c->num; n++) {
		struct wsum *w = &c->w[n];

		if (*w->hold)
			continue;	/* "when TRUE, the sum output does not change" */
		for (m = 0; m < w->num_bits; m++) {
			bits[m] = *w->in[m];
			weights[m] = w->weight[m];
		}
		*w->sum = wsum_compute(bits, weights, w->num_bits, w->offset);
	}
}

static int export_wsum(struct wsum *w, int n, int bits)
{
	int m, err;

	w->num_bits = bits;
	err = hal_pin_bit_newf(HAL_IN, &w->hold, comp_id, "wsum.%d.hold", n);
	if (!err)
		err = hal_pin_s32_newf(HAL_OUT, &w->sum, comp_id, "wsum.%d.sum", n);
	if (!err)
		err = hal_param_s32_newf(HAL_RW, &w->offset, comp_id, "wsum.%d.offset", n);
	for (m = 0; !err && m < bits; m++) {
		err = hal_pin_bit_newf(HAL_IN, &w->in[m], comp_id, "wsum.%d.bit.%d.in", n, m);
		if (!err)
			err = hal_param_s32_newf(HAL_RW, &w->weight[m], comp_id,
						 "wsum.%d.bit.%d.weight", n, m);
		w->weight[m] = 1 << m;
	}
	return err;
}

int rtapi_app_main(void)
{
	struct wsum_comp *c;
	int num, n, err;

	for (num = 0; num < WSUM_MAX_SUMMERS && wsum_sizes[num] != -1; num++) {
		if (wsum_sizes[num] < 1 || wsum_sizes[num] > WSUM_MAX_BITS) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"weighted_sum: wsum_sizes= entry %d is %d, must be 1..%d bits\n",
					num + 1, wsum_sizes[num], WSUM_MAX_BITS);
			return -EINVAL;
		}
	}
	if (num == 0) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"weighted_sum: no wsum_sizes= given; e.g. wsum_sizes=8,4 makes two summers\n");
		return -EINVAL;
	}
	c = comp_setup("weighted_sum", sizeof(*c), &comp_id, &err);
	if (!c)
		return err;
	c->num = num;
	for (n = 0; !err && n < num; n++)
		err = export_wsum(&c->w[n], n, wsum_sizes[n]);
	if (!err)
		err = hal_export_funct("process_wsums", process_wsums, c, 0, 0, comp_id);
	return comp_finish(comp_id, err);
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
