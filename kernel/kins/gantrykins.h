/* SPDX-License-Identifier: GPL-2.0-or-later */
/* gantrykins.h - what gantrykins.c (init, pins) and gantrykins_fp.c share. */
#ifndef GANTRYKINS_H
#define GANTRYKINS_H

#include "hal.h"
#include "kinematics.h"
#include "kins_coords.h"

#define GANTRYKINS_JOINTS 9	/* EMC2's EMCMOT_MAX_JOINTS: joints beyond are not mapped */

/* In HAL memory: gantrykins.joint-N, the axis index 0..8 of joint N (-1: none).
 * Written by halcmd (setp), read by forward and inverse. */
struct gantrykins_params {
	hal_s32_t joint[GANTRYKINS_JOINTS];
};
COMP_FP_LOCAL extern struct gantrykins_params *gantrykins;

#endif /* GANTRYKINS_H */
