/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kinstest.h - what kinstest.c (init, pins) and kinstest_fp.c (the update) share. */
#ifndef KINSTEST_H
#define KINSTEST_H

#include "hal.h"
#include "kinematics.h"
#include "kins_bind.h"
#include "fp_split.h"

/* In HAL memory. Pins named in kinstest.c; written by update() unless IN. */
struct kinstest {
	int joints;			/* how many joint pins (joints=) */
	hal_float_t *joint_in[KINS_MAX_JOINTS], *joint_out[KINS_MAX_JOINTS];
	hal_float_t *pos_in[KINS_NUM_AXES], *pos_out[KINS_NUM_AXES], *home[KINS_NUM_AXES];
	hal_u32_t *fwd_fflags, *fwd_iflags, *inv_iflags, *inv_fflags;
	hal_s32_t *fwd_result, *inv_result;
	hal_s32_t *switch_type, *switch_result;
	hal_s32_t *type;		/* set at load */
	hal_bit_t *switchable;		/* set at load */
	hal_u32_t *cycles;		/* updates run, so tests can wait for results */
	rtapi_s32 applied_switch;	/* private to update(): the last switch type asked for */
	bool have_world;		/* private to update(): the last forward succeeded */
	EmcPose world;			/* private to update(): its result, the next guess */
};

/* The loaded kinematics module, found at load (kins_bind.h). Not in HAL memory: HAL
 * users may write there, and these are the addresses the update calls. */
COMP_FP_LOCAL extern struct kins_ops kinstest_kins;

COMP_FP_LOCAL void kinstest_update(void *arg, long period_ns);

#endif /* KINSTEST_H */
