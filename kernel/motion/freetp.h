/* SPDX-License-Identifier: GPL-2.0-or-later */
/* freetp.h - the free-mode trapezoid planner (motion.md 12, LinuxCNC's simple_tp):
 * one per joint (FREE state: jogs, homing moves) and one per axis (TELEOP jogs).
 * HAL-free and time-free (the period is an argument) so unit tests drive it. */
#ifndef MOTION_FREETP_H
#define MOTION_FREETP_H

#include "rtapi.h"

#ifdef __cplusplus
extern "C" {
#endif

struct freetp {
	double pos_cmd;		/* target position (the caller sets it) */
	double max_vel;		/* > 0 */
	double max_acc;		/* > 0 */
	double curr_pos;	/* planner output */
	double curr_vel;
	bool enable;		/* FALSE: decelerate to a stop, target := current position */
	bool active;		/* moving, or not yet at the target */
};

/* One period of period_s seconds: the velocity moves toward the highest velocity from
 * which the target can still be reached at max_acc, clamped to +-max_vel, and changes by
 * at most max_acc * period_s; then curr_pos += curr_vel * period_s. */
void freetp_update(struct freetp *tp, double period_s);

/* Put the planner at rest at pos (mode changes, homing coordinate shifts). */
void freetp_reset(struct freetp *tp, double pos);

#ifdef __cplusplus
}
#endif
#endif
