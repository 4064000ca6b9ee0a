/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sampler_fp.h - what sampler.c (init, exit, HAL glue; no SSE in the kernel flavor) and
 * sampler_fp.c (its floating-point realtime functions) share. */
#ifndef SAMPLER_FP_H
#define SAMPLER_FP_H

#include "rtapi.h"
#include "hal.h"
#include "streamer_fifo.h"
#include "fifo_module.h"
#include "fp_split.h"


struct sampler {		/* in hal_malloc() memory, one per FIFO */
	struct hal_fifo_hdr *hdr;	/* shared memory: sample() is the producer */
	struct hal_fifo_rt fifo;	/* sample()'s own geometry and 'in': never from hdr */
	union hal_fifo_value *data;
	hal_bit_t *enable;		/* read by sample() */
	hal_s32_t *curr_depth;		/* written by sample() */
	hal_bit_t *full;		/* written by sample() */
	hal_s32_t *overruns;		/* I/O pin: sample() counts up, setp resets */
	hal_s32_t *sample_num;		/* I/O pin: sample() counts up, setp resets */
	bool gap;			/* private to sample(): a sample was dropped */
	int num_pins;
	char type[HAL_FIFO_MAX_PINS];	/* enum hal_fifo_type per pin */
	union fifo_pin_ptr pins[HAL_FIFO_MAX_PINS];
};

/* Realtime functions exported with uses_fp = 1, in sampler_fp.c. */
COMP_FP_LOCAL void sample(void *arg, long period_ns);

#endif /* SAMPLER_FP_H */
