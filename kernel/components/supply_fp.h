/* SPDX-License-Identifier: GPL-2.0-or-later */
/* supply_fp.h - what supply.c (init, exit, HAL glue; no SSE in the kernel flavor) and
 * supply_fp.c (its floating-point realtime functions) share. */
#ifndef SUPPLY_FP_H
#define SUPPLY_FP_H

#include "rtapi.h"
#include "hal.h"
#include "fp_split.h"

#define SUPPLY_MAX_CHAN 8

struct supply {			/* in hal_malloc() memory */
	hal_bit_t *q, *q_not;	/* written by update */
	hal_float_t *variable, *variable_neg;	/* written by update */
	hal_bit_t d;		/* RW param */
	hal_float_t value;	/* RW param */
};

/* Realtime functions exported with uses_fp = 1, in supply_fp.c. */
COMP_FP_LOCAL void supply_update(void *arg, long period_ns);

#endif /* SUPPLY_FP_H */
