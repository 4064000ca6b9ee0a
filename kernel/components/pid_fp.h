/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pid_fp.h - what pid.c (init, exit, HAL glue; no SSE in the kernel flavor) and
 * pid_fp.c (its floating-point realtime functions) share. */
#ifndef PID_FP_H
#define PID_FP_H

#include "rtapi.h"
#include "hal.h"
#include "pid_core.h"
#include "pid_pins.h"
#include "fp_split.h"

#define PID_MAX 16		/* pid(9): a maximum of sixteen controllers */
#define PID_DEFAULT 3		/* pid(9): with neither num_chan= nor names= */

struct pid_loop {			/* in hal_malloc() memory, one per loop */
	struct pid_pins pins;
	struct pid_state st;	/* private to do_pid_calcs() */
};

/* Realtime functions exported with uses_fp = 1, in pid_fp.c. */
COMP_FP_LOCAL void pid_do_calcs(void *arg, long period_ns);

#endif /* PID_FP_H */
