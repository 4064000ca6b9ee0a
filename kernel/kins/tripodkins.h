/* SPDX-License-Identifier: GPL-2.0-or-later */
/* tripodkins.h - what tripodkins.c (init, pins) and tripodkins_fp.c share. */
#ifndef TRIPODKINS_H
#define TRIPODKINS_H

#include "hal.h"
#include "kinematics.h"
#include "fp_split.h"

/* In HAL memory: the pins tripodkins.Bx, .Cx, .Cy (I/O floats, default 1.0). */
struct tripodkins_pins {
	hal_float_t *bx, *cx, *cy;
};
COMP_FP_LOCAL extern struct tripodkins_pins *tripodkins;

/* Init, between rtapi_fpu_begin() and rtapi_fpu_end(): the pins' defaults. */
COMP_FP_LOCAL void tripodkins_defaults(struct tripodkins_pins *p);

#endif /* TRIPODKINS_H */
