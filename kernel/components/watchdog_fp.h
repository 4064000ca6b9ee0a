/* SPDX-License-Identifier: GPL-2.0-or-later */
/* watchdog_fp.h - what watchdog.c (init, exit, HAL glue; no SSE in the kernel flavor) and
 * watchdog_fp.c (its floating-point realtime functions) share. */
#ifndef WATCHDOG_FP_H
#define WATCHDOG_FP_H

#include "rtapi.h"
#include "hal.h"
#include "fp_split.h"

#define WATCHDOG_MAX_INPUTS 32

struct watchdog_input {
	hal_bit_t *in;
	hal_float_t *timeout;		/* seconds, read by set-timeouts */
	rtapi_u64 timeout_ns;		/* written by set-timeouts, read by process (untorn) */
	rtapi_s64 left_ns;		/* process only: time left for the next transition */
	hal_bit_t last;			/* process only: level seen in the previous period */
};

struct watchdog {			/* in hal_malloc() memory */
	hal_bit_t *enable_in;
	hal_bit_t *ok_out;		/* written by process only */
	rtapi_u32 restarts;		/* written by set-timeouts: enable-in rising edges seen */
	rtapi_u32 restarts_seen;	/* process only */
	hal_bit_t last_enable;		/* set-timeouts only */
	hal_bit_t fault;		/* process only: a timeout, or never started */
	struct watchdog_input input[WATCHDOG_MAX_INPUTS];
};

/* num_inputs= (watchdog.c), read by set-timeouts */
extern COMP_FP_LOCAL int num_inputs;

/* Realtime functions exported with uses_fp = 1, in watchdog_fp.c. */
COMP_FP_LOCAL void watchdog_set_timeouts(void *arg, long period);

#endif /* WATCHDOG_FP_H */
