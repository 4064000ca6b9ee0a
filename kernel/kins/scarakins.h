/* SPDX-License-Identifier: GPL-2.0-or-later */
/* scarakins.h - what scarakins.c (init, pins, switch) and scarakins_fp.c share. */
#ifndef SCARAKINS_H
#define SCARAKINS_H

#include "hal.h"
#include "kins_glue.h"

/* In HAL memory: the pins scarakins.D1 ... scarakins.D6 (float IN), and the switch. */
struct scarakins_state {
	hal_float_t *d[6];
	struct kins_switch sw;
};
COMP_FP_LOCAL extern struct scarakins_state *scarakins;

COMP_FP_LOCAL void scarakins_defaults(struct scarakins_state *s);

#endif /* SCARAKINS_H */
