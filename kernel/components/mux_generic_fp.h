/* SPDX-License-Identifier: GPL-2.0-or-later */
/* mux_generic_fp.h - what mux_generic.c (init, exit, HAL glue, the integer-only
 * function; no SSE in the kernel flavor) and mux_generic_fp.c (the function of muxes
 * with a float input or output) share. */
#ifndef MUX_GENERIC_FP_H
#define MUX_GENERIC_FP_H

#include "rtapi.h"
#include "hal.h"
#include "mux_generic_core.h"
#include "fp_split.h"

#define MUX_GEN_MAX_BITS 10	/* sel-bit pins of the largest mux, 1024 inputs */

union mux_gen_pin {		/* which member follows the mux's input or output type */
	hal_bit_t *b;
	hal_float_t *f;
	hal_s32_t *s;
	hal_u32_t *u;
};

struct mux_gen {		/* in hal_malloc() memory, one per config= entry */
	struct mux_gen_cfg cfg;
	int num_bits;			/* sel-bit pins */
	hal_bit_t *suppress;		/* in: suppress-no-input */
	hal_u32_t *debounce_us;		/* in */
	hal_u32_t *sel_int;		/* in */
	hal_bit_t *sel_bit[MUX_GEN_MAX_BITS];	/* in */
	union mux_gen_pin out;		/* written by the mux's function */
	hal_float_t elapsed;		/* param ro: debounce timer in s (float muxes) */
	hal_s32_t selected;		/* param ro: the selection in use */
	struct mux_gen_sel_state st;	/* private to the mux's function */
	union mux_gen_pin in[];		/* cfg.size input pins */
};

/* sel-int plus the binary value of the sel-bit pins (integer only). */
static inline rtapi_s64 mux_gen_sel_value(const struct mux_gen *m)
{
	rtapi_s64 sel = *m->sel_int;
	int i;

	for (i = 0; i < m->num_bits; i++)
		if (*m->sel_bit[i])
			sel += (rtapi_s64)1 << i;
	return sel;
}

/* Realtime function of a mux with a float input or output, exported with uses_fp = 1. */
COMP_FP_LOCAL void mux_gen_update_fp(void *arg, long period_ns);

#endif /* MUX_GENERIC_FP_H */
