/* SPDX-License-Identifier: GPL-2.0-or-later */
/* at_pid_fp.h - what at_pid.c (init, exit, HAL glue; no SSE in the kernel flavor) and
 * at_pid_fp.c (its floating-point realtime functions) share. */
#ifndef AT_PID_FP_H
#define AT_PID_FP_H

#include "rtapi.h"
#include "hal.h"
#include "pid_core.h"
#include "pid_pins.h"
#include "at_pid_core.h"
#include "fp_split.h"

#define AT_PID_MAX 16
#define AT_PID_DEFAULT 3

struct at_pid {			/* in hal_malloc() memory, one per loop */
	struct pid_pins pins;
	hal_bit_t *tune_mode;	/* in */
	hal_bit_t *tune_start;	/* io: cleared by do-pid-calcs when tuning ends */
	hal_float_t *ultimate_gain, *ultimate_period;	/* out, debug=1 only */
	hal_u32_t tune_type, tune_cycles;	/* params, written by halcmd */
	hal_float_t tune_effort;
	struct pid_state st;	/* private to do-pid-calcs() */
	struct at_pid_tune tune;	/* private to do-pid-calcs() */
};

/* Realtime functions exported with uses_fp = 1, in at_pid_fp.c. */
COMP_FP_LOCAL void at_pid_do_calcs(void *arg, long period_ns);

#endif /* AT_PID_FP_H */
