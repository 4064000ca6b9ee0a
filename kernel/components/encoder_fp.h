/* SPDX-License-Identifier: GPL-2.0-or-later */
/* encoder_fp.h - what encoder.c (init, exit, HAL glue; no SSE in the kernel flavor) and
 * encoder_fp.c (its floating-point realtime functions) share. */
#ifndef ENCODER_FP_H
#define ENCODER_FP_H

#include "rtapi.h"
#include "hal.h"
#include "encoder_core.h"
#include "fp_split.h"

#define ENCODER_MAX 8		/* encoder(9): a maximum of eight channels */
#define ENCODER_DEFAULT 3	/* encoder(9): with neither num_chan= nor names= */
#define FLOAT_ONE_BITS 0x3ff0000000000000ULL	/* 1.0, stored without FP at init */

struct encoder_chan {		/* in hal_malloc() memory */
	hal_bit_t *phase_a, *phase_b, *phase_z, *reset;	/* in */
	hal_bit_t *latch_input, *latch_rising, *latch_falling;	/* in */
	hal_s32_t *missing_teeth;	/* in */
	hal_float_t *min_speed;	/* in */
	hal_bit_t *index_enable;	/* io: cleared by capture-position on the index */
	hal_bit_t *counter_mode, *x4_mode;	/* io, read by update-counters */
	hal_float_t *scale;	/* io, read by capture-position */
	hal_s32_t *rawcounts;	/* out, written by update-counters */
	hal_s32_t *counts, *counts_latched;	/* out, written by capture-position */
	hal_float_t *position, *position_interpolated, *position_latched, *velocity;
	struct enc_update_state up;	/* private to update-counters */
	struct enc_shared shared;	/* update-counters -> capture-position */
	struct enc_acks acks;	/* capture-position -> update-counters */
	struct enc_capture_state cap;	/* private to capture-position */
};

struct encoder_set {		/* in hal_malloc() memory: the functions' argument */
	int num;
	struct encoder_chan chan[];
};

/* Realtime functions exported with uses_fp = 1, in encoder_fp.c. */
COMP_FP_LOCAL void encoder_capture_position(void *arg, long period_ns);

#endif /* ENCODER_FP_H */
