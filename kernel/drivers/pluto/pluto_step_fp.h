/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pluto_step_fp.h - what pluto_step.c (init, exit, HAL glue; no SSE in the kernel
 * flavor) and pluto_step_fp.c (the read and write functions) share. */
#ifndef PLUTO_STEP_FP_H
#define PLUTO_STEP_FP_H

#include "rtapi.h"
#include "hal.h"
#include "hal_parport.h"
#include "pluto_io.h"
#include "fp_split.h"

#define PLUTO_STEP_TICK_NS 1600		/* the step generators' tick, 64 clocks of 40 MHz */
#define PLUTO_STEP_TMAX    15		/* the firmware's 4-bit timers, in ticks */

struct pluto_stepgen {
	hal_float_t *position_cmd, *velocity_fb, *position_fb;
	hal_s32_t *counts;
	hal_bit_t *enable, *reset;
	hal_float_t scale, maxvel;	/* RW */
	rtapi_s64 count64, zero;	/* the 21-bit position, extended */
	double old_cmd;			/* last position-cmd */
	int maxvel_warned;
};

struct pluto_step {		/* HAL memory */
	hal_parport_t port;
	int epp_wide;
	int speedrange;		/* the firmware's tap: one step = 2^(11 + speedrange) units */
	rtapi_u16 watchdog_bit;
	struct pluto_stepgen sg[4];
	hal_bit_t step_polarity;			/* RW */
	hal_u32_t steplen, stepspace, dirtime;		/* RW, ns */
	struct pluto_io io;	/* dout 00..13, din 00..15 */
	hal_float_t debug_2, debug_3;
};

/* Realtime functions exported with uses_fp = 1. */
COMP_FP_LOCAL void pluto_step_read(void *arg, long period);
COMP_FP_LOCAL void pluto_step_write(void *arg, long period);

#endif /* PLUTO_STEP_FP_H */
