/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sim_encoder_fp.h - what sim_encoder.c (init, exit, HAL glue; no SSE in the kernel flavor) and
 * sim_encoder_fp.c (its floating-point realtime functions) share. */
#ifndef SIM_ENCODER_FP_H
#define SIM_ENCODER_FP_H

#include "rtapi.h"
#include "hal.h"
#include "sim_encoder_core.h"
#include "fp_split.h"

#define SIM_ENCODER_MAX 8
#define FLOAT_ONE_BITS 0x3ff0000000000000ULL	/* 1.0, stored without FP at init */

struct sim_encoder_chan {	/* in hal_malloc() memory */
	hal_bit_t *phase_a, *phase_b, *phase_z;	/* out, written by make-pulses */
	hal_float_t *speed;	/* in, read by update-speed */
	hal_u32_t ppr;		/* param rw, read by update-speed */
	hal_float_t scale;	/* param rw, read by update-speed */
	struct sim_enc_shared shared;	/* update-speed <-> make-pulses */
	struct sim_enc_state st;	/* private to make-pulses */
};

struct sim_encoder_set {	/* in hal_malloc() memory: the functions' argument */
	int num;
	struct sim_encoder_chan chan[];
};

/* Realtime functions exported with uses_fp = 1, in sim_encoder_fp.c. */
COMP_FP_LOCAL void sim_encoder_update_speed(void *arg, long period_ns);

#endif /* SIM_ENCODER_FP_H */
