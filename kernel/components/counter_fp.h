/* SPDX-License-Identifier: GPL-2.0-or-later */
/* counter_fp.h - what counter.c (init, exit, HAL glue; no SSE in the kernel flavor) and
 * counter_fp.c (its floating-point realtime functions) share. */
#ifndef COUNTER_FP_H
#define COUNTER_FP_H

#include "rtapi.h"
#include "hal.h"
#include "encoder_core.h"
#include "fp_split.h"

#define COUNTER_MAX 8
#define FLOAT_ONE_BITS 0x3ff0000000000000ULL	/* 1.0, stored without FP at init */

struct counter_chan {		/* in hal_malloc() memory */
	hal_bit_t *phase_a, *phase_z;	/* in */
	hal_bit_t *index_enable;	/* io: cleared by capture-position on the index */
	hal_bit_t *reset;	/* io, read by capture-position */
	hal_s32_t *counts;	/* out, written by capture-position */
	hal_float_t *position, *velocity;	/* out, written by capture-position */
	hal_float_t scale;	/* param rw */
	hal_s32_t rawcounts;	/* param ro, written by update-counters */
	struct enc_update_state up;	/* private to update-counters */
	struct enc_shared shared;	/* update-counters -> capture-position */
	struct enc_acks acks;	/* capture-position -> update-counters */
	struct enc_capture_state cap;	/* private to capture-position */
	bool index_armed;	/* index-enable as capture-position last saw it; read by update-counters */
};

struct counter_set {		/* in hal_malloc() memory: the functions' argument */
	int num;
	struct counter_chan chan[];
};

/* Realtime functions exported with uses_fp = 1, in counter_fp.c. */
COMP_FP_LOCAL void counter_capture_position(void *arg, long period_ns);

#endif /* COUNTER_FP_H */
