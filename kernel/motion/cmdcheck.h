/* SPDX-License-Identifier: GPL-2.0-or-later */
/* cmdcheck.h - the field checks of one command of the shared command slot, before
 * motion uses it (motion_if.h): command number known, indices in range for this
 * configuration, numbers finite and in their domain. HAL-free so unit tests can feed
 * it hostile commands. State-dependent preconditions (enabled, FREE, homed...) are
 * the handler's (command_fp.c). */
#ifndef MOTION_CMDCHECK_H
#define MOTION_CMDCHECK_H

#include "rtapi.h"
#include "motion_if.h"

#ifdef __cplusplus
extern "C" {
#endif

struct cmdcheck_config {
	int num_joints;
	int num_spindles;
	int num_dout;
	int num_aout;
	bool teleop;		/* jogs address axes (TELEOP) instead of joints */
};

/* MOTION_CMD_OK, or UNKNOWN / INVALID_PARAMS with a one-line reason in msg. */
int cmdcheck(const struct motion_command *c, const struct cmdcheck_config *cfg, char *msg,
	     int msglen);

/* The command's name ("JOG_CONT"), or "?" for a number outside the enum. */
const char *cmdcheck_name(int command);

#ifdef __cplusplus
}
#endif
#endif
