/* SPDX-License-Identifier: GPL-2.0-or-later */
/* genhexkins.h - what genhexkins.c (init, pins, switch) and genhexkins_fp.c share. */
#ifndef GENHEXKINS_H
#define GENHEXKINS_H

#include "hal.h"
#include "kins_glue.h"
#include "kins_models.h"

/* In HAL memory: the pins of genhexkins (see genhexkins.c), and the switch. */
struct genhexkins_state {
	hal_float_t *base[KINS_HEX_STRUTS][3], *platform[KINS_HEX_STRUTS][3];	/* IN */
	hal_float_t *base_n[KINS_HEX_STRUTS][3], *platform_n[KINS_HEX_STRUTS][3]; /* IN */
	hal_float_t *screw_lead, *spindle_offset, *tool_offset;		/* IN */
	hal_float_t *max_error, *criterion;				/* IN */
	hal_u32_t *limit_iterations;					/* IN */
	hal_float_t *correction[KINS_HEX_STRUTS];	/* OUT: written by the inverse */
	hal_u32_t *last_iterations, *max_iterations;	/* OUT: written by the forward */
	hal_bit_t *fwd_kins_fail;			/* OUT: written by the forward */
	hal_float_t *pos[6];		/* OUT x y z a b c: the last forward result */
	struct kins_switch sw;
};
COMP_FP_LOCAL extern struct genhexkins_state *genhexkins;

COMP_FP_LOCAL void genhexkins_defaults(struct genhexkins_state *s);

#endif /* GENHEXKINS_H */
