/* SPDX-License-Identifier: GPL-2.0-or-later */
/* encoder_ratio_fp.h - what encoder_ratio.c (init, exit, HAL glue; no SSE in the kernel flavor) and
 * encoder_ratio_fp.c (its floating-point realtime functions) share. */
#ifndef ENCODER_RATIO_FP_H
#define ENCODER_RATIO_FP_H

#include "rtapi.h"
#include "hal.h"
#include "encoder_ratio_core.h"
#include "fp_split.h"

#define ENCODER_RATIO_MAX 8	/* encoder_ratio(9): up to eight axis pairs */

struct encoder_ratio_chan {	/* in hal_malloc() memory */
	hal_bit_t *master_a, *master_b, *slave_a, *slave_b, *enable;	/* in, read by sample */
	hal_float_t *error;	/* out, written by update */
	hal_u32_t master_ppr, slave_ppr, master_teeth, slave_teeth;	/* params, read by update */
	struct enc_ratio_state st;	/* private to sample */
	struct enc_ratio_counts counts;	/* sample -> update */
};

struct encoder_ratio_set {	/* in hal_malloc() memory: the functions' argument */
	int num;
	struct encoder_ratio_chan chan[];
};

/* Realtime functions exported with uses_fp = 1, in encoder_ratio_fp.c. */
COMP_FP_LOCAL void encoder_ratio_update(void *arg, long period_ns);

#endif /* ENCODER_RATIO_FP_H */
