/* SPDX-License-Identifier: GPL-2.0-or-later */
/* maxkins.h - what maxkins.c (init, pins) and maxkins_fp.c share. */
#ifndef MAXKINS_H
#define MAXKINS_H

#include "hal.h"
#include "kinematics.h"
#include "fp_split.h"

/* In HAL memory: maxkins.pivot-length (float I/O, default 0.666) and
 * maxkins.conventional-directions (bit IN, default FALSE). */
struct maxkins_pins {
	hal_float_t *pivot_length;
	hal_bit_t *conventional;
};
COMP_FP_LOCAL extern struct maxkins_pins *maxkins;

COMP_FP_LOCAL void maxkins_defaults(struct maxkins_pins *p);

#endif /* MAXKINS_H */
