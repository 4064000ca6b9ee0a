/* SPDX-License-Identifier: GPL-2.0-or-later */
/* siggen_fp.h - what siggen.c (init, exit, HAL glue; no SSE in the kernel flavor) and
 * siggen_fp.c (its floating-point realtime functions) share. */
#ifndef SIGGEN_FP_H
#define SIGGEN_FP_H

#include "rtapi.h"
#include "hal.h"
#include "siggen_core.h"
#include "fp_split.h"

#define SIGGEN_MAX 16		/* siggen(9): a maximum of sixteen channels */
#define FLOAT_ONE_BITS 0x3ff0000000000000ULL	/* 1.0 */

struct siggen {			/* in hal_malloc() memory, one per generator */
	hal_float_t *frequency, *amplitude, *offset;	/* inputs, read by update() */
	hal_float_t *sine, *cosine, *triangle, *sawtooth, *square;	/* written by update() */
	hal_bit_t *clock;	/* written by update() */
	struct siggen_state st;	/* private to update() */
};

/* Realtime functions exported with uses_fp = 1, in siggen_fp.c. */
COMP_FP_LOCAL void siggen_update(void *arg, long period_ns);

#endif /* SIGGEN_FP_H */
