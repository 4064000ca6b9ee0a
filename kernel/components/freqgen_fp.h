/* SPDX-License-Identifier: GPL-2.0-or-later */
/* freqgen_fp.h - what freqgen.c (init, exit, HAL glue; no SSE in the kernel flavor) and
 * freqgen_fp.c (its floating-point realtime functions) share. */
#ifndef FREQGEN_FP_H
#define FREQGEN_FP_H

#include "rtapi.h"
#include "hal.h"
#include "stepgen_core.h"
#include "stepgen_loop.h"
#include "fp_split.h"

#define FLOAT_ONE_BITS 0x3ff0000000000000ULL	/* 1.0, set without FP instructions */

struct freqgen_chan {		/* in hal_malloc() memory */
	int type;
	hal_float_t *velocity;	/* read by update-freq */
	hal_s32_t *counts;	/* written by capture-position */
	hal_float_t *position_fb;	/* written by capture-position */
	hal_bit_t *out[STEPGEN_MAX_PHASES];
	int num_out;
	hal_float_t frequency;	/* RO: written by update-freq */
	hal_float_t maxaccel, maxfreq, position_scale, velocity_scale;	/* RW */
	hal_s32_t rawcounts;	/* RO: written by make-pulses */
	hal_u32_t steplen, stepspace, dirsetup, dirhold;	/* periods, RW */
	struct stepgen_timing timing;	/* written by update-freq */
	struct stepgen_pulse pulse;
	struct stepgen_loop loop;	/* update-freq; vel in steps/s */
};

struct freqgen_comp {
	hal_u32_t base_period_ns;	/* written by make-pulses */
	int num_chan;
	struct freqgen_chan chan[STEPGEN_MAX_CHAN];
};

/* Realtime functions exported with uses_fp = 1, in freqgen_fp.c. */
COMP_FP_LOCAL void update_freq(void *arg, long period_ns);
COMP_FP_LOCAL void capture_position(void *arg, long period_ns);

#endif /* FREQGEN_FP_H */
