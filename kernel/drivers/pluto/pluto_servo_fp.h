/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pluto_servo_fp.h - what pluto_servo.c (init, exit, HAL glue; no SSE in the kernel
 * flavor) and pluto_servo_fp.c (the read and write functions) share. */
#ifndef PLUTO_SERVO_FP_H
#define PLUTO_SERVO_FP_H

#include "rtapi.h"
#include "hal.h"
#include "hal_parport.h"
#include "pluto_io.h"
#include "fp_split.h"

struct pluto_encoder {
	hal_s32_t *count;
	hal_float_t *position, *velocity;
	hal_bit_t *reset, *index_enable;
	hal_float_t scale;			/* RW */
	rtapi_s64 count64, index64, zero;	/* the 14-bit counter, extended */
};

struct pluto_pwm {
	hal_float_t *value;
	hal_bit_t *enable;
	hal_float_t offset, scale, max_dc, min_dc;	/* RW */
	hal_bit_t pwmdir;				/* RW */
};

struct pluto_servo {		/* HAL memory */
	hal_parport_t port;
	int epp_wide;
	rtapi_u16 control_bits;	/* outputs word bits 14 (watchdog), 13 (test mode) */
	struct pluto_encoder enc[4];
	hal_bit_t z_polarity;
	struct pluto_pwm pwm[4];
	hal_bit_t is_pdm;
	struct pluto_io io;	/* dout 00..19, din 00..19 */
};

/* Realtime functions exported with uses_fp = 1. */
COMP_FP_LOCAL void pluto_servo_read(void *arg, long period);
COMP_FP_LOCAL void pluto_servo_write(void *arg, long period);

#endif /* PLUTO_SERVO_FP_H */
