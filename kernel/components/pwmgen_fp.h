/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pwmgen_fp.h - what pwmgen.c (init, exit, HAL glue; no SSE in the kernel flavor) and
 * pwmgen_fp.c (its floating-point realtime functions) share. */
#ifndef PWMGEN_FP_H
#define PWMGEN_FP_H

#include "rtapi.h"
#include "hal.h"
#include "pwmgen_core.h"
#include "fp_split.h"

#define FLOAT_ONE_BITS 0x3ff0000000000000ULL	/* 1.0 */

struct pwmgen_chan {		/* in hal_malloc() memory */
	int type;		/* output type, fixed at load */
	hal_float_t *value;	/* read by update */
	hal_bit_t *enable;	/* read by update */
	hal_bit_t *out[2];	/* pwm [+ dir], or up + down: written by make-pulses */
	hal_float_t scale, offset, pwm_freq, min_dc, max_dc;	/* RW, read by update */
	hal_bit_t dither;	/* RW */
	hal_float_t curr_dc;	/* RO: written by update */
	struct pwmgen_plan plan;	/* written by update, read by make-pulses */
	struct pwmgen_pulse pulse;	/* make-pulses */
};

struct pwmgen_comp {
	hal_u32_t base_period_ns;	/* written by make-pulses */
	int num_chan;
	struct pwmgen_chan chan[PWMGEN_MAX_CHAN];
};

/* Realtime functions exported with uses_fp = 1, in pwmgen_fp.c. */
COMP_FP_LOCAL void update(void *arg, long period_ns);

#endif /* PWMGEN_FP_H */
