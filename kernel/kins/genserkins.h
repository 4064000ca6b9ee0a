/* SPDX-License-Identifier: GPL-2.0-or-later */
/* genserkins.h - what genserkins.c (init, pins, switch) and genserkins_fp.c share. */
#ifndef GENSERKINS_H
#define GENSERKINS_H

#include "hal.h"
#include "kins_glue.h"
#include "kins_models.h"

/* In HAL memory: the pins of genserkins (see genserkins.c), and the switch. */
struct genserkins_state {
	hal_float_t *a[KINS_GENSER_LINKS], *alpha[KINS_GENSER_LINKS], *d[KINS_GENSER_LINKS];
	hal_s32_t *unrotate[KINS_GENSER_LINKS];
	hal_u32_t *max_iterations;	/* IN */
	hal_u32_t *last_iterations;	/* OUT: written by the inverse */
	struct kins_switch sw;
};
COMP_FP_LOCAL extern struct genserkins_state *genserkins;

COMP_FP_LOCAL void genserkins_defaults(struct genserkins_state *s);

#endif /* GENSERKINS_H */
