/* SPDX-License-Identifier: GPL-2.0-or-later */
/* stepgen_fp.h - what stepgen.c (init, exit, HAL glue; no SSE in the kernel flavor) and
 * stepgen_fp.c (its floating-point realtime functions) share. */
#ifndef STEPGEN_FP_H
#define STEPGEN_FP_H

#include "rtapi.h"
#include "hal.h"
#include "stepgen_core.h"
#include "stepgen_loop.h"
#include "fp_split.h"

#define FLOAT_ONE_BITS 0x3ff0000000000000ULL	/* 1.0 */

struct stepgen_chan {		/* in hal_malloc() memory */
	int type;		/* step type, fixed at load */
	bool velocity_mode;	/* ctrl_type v */
	const struct stepgen_pattern *pat;	/* types 2-15 */
	hal_float_t *cmd;	/* position-cmd or velocity-cmd: read by update-freq */
	hal_bit_t *enable;	/* read by make-pulses and update-freq */
	hal_s32_t *counts;	/* written by capture-position */
	hal_float_t *position_fb;	/* written by capture-position */
	hal_bit_t *out[STEPGEN_MAX_PHASES];	/* step/dir, up/down or phase-A..E */
	int num_out;
	hal_float_t position_scale, maxvel, maxaccel;	/* RW params, read by update-freq */
	hal_float_t frequency;	/* RO param: written by update-freq */
	hal_u32_t steplen, stepspace, dirsetup, dirhold, dirdelay;	/* ns, RW */
	hal_s32_t rawcounts;	/* RO param: written by make-pulses */
	struct stepgen_timing timing;	/* periods: written by update-freq */
	struct stepgen_pulse pulse;	/* make-pulses (addval: update-freq) */
	struct stepgen_loop loop;	/* update-freq */
};

struct stepgen_comp {
	hal_u32_t base_period_ns;	/* make-pulses period: written by make-pulses */
	int num_chan;
	struct stepgen_pattern user_pat;	/* type 15 */
	struct stepgen_chan chan[STEPGEN_MAX_CHAN];
};

/* Realtime functions exported with uses_fp = 1, in stepgen_fp.c. */
COMP_FP_LOCAL void update_freq(void *arg, long period_ns);
COMP_FP_LOCAL void capture_position(void *arg, long period_ns);

#endif /* STEPGEN_FP_H */
