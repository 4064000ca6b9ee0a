/* SPDX-License-Identifier: GPL-2.0-or-later */
/* streamer_fp.h - what streamer.c (init, exit, HAL glue; no SSE in the kernel flavor) and
 * streamer_fp.c (its floating-point realtime functions) share. */
#ifndef STREAMER_FP_H
#define STREAMER_FP_H

#include "rtapi.h"
#include "hal.h"
#include "streamer_fifo.h"
#include "fifo_module.h"
#include "fp_split.h"


#define STREAMER_CLOCK_FREE 0		/* clock-mode: a record every period */
#define STREAMER_CLOCK_FALLING 1	/* a record on each falling edge of clock */
#define STREAMER_CLOCK_RISING 2
#define STREAMER_CLOCK_BOTH 3

struct streamer {		/* in hal_malloc() memory, one per FIFO */
	struct hal_fifo_hdr *hdr;	/* shared memory: update() is the consumer */
	struct hal_fifo_rt fifo;	/* update()'s own geometry and 'out': never from hdr */
	union hal_fifo_value *data;
	hal_s32_t *curr_depth;		/* written by update() */
	hal_bit_t *empty;		/* written by update() */
	hal_bit_t *enable;		/* read by update() */
	hal_s32_t *underruns;		/* I/O pin: update() counts up, setp resets */
	hal_bit_t *clock;		/* read by update() */
	hal_s32_t *clock_mode;		/* read by update(): STREAMER_CLOCK_* */
	bool last_clock;		/* private to update(): clock in the previous period */
	int num_pins;
	char type[HAL_FIFO_MAX_PINS];	/* enum hal_fifo_type per pin */
	union fifo_pin_ptr pins[HAL_FIFO_MAX_PINS];
};

/* Realtime functions exported with uses_fp = 1, in streamer_fp.c. */
COMP_FP_LOCAL void update(void *arg, long period_ns);

#endif /* STREAMER_FP_H */
