/* SPDX-License-Identifier: GPL-2.0-or-later */
/* coord.h - motmod's side of coordinated motion (COORD state): the segment queue and
 * the trajectory planner (kernel/motion/tp/, tp.h) behind a few calls, so the command
 * handler and the controller do not depend on the planner's own interface. World
 * positions are EmcPose; every function is FP (coord_fp.c). */
#ifndef MOTION_COORD_H
#define MOTION_COORD_H

#include "motmod_priv.h"

/* load time, inside rtapi_fpu_begin/end: the planner in its static memory; 0 or -ENOMEM */
int coord_init_values(struct motmod *m);
int coord_queue_size(struct motmod *m);

/* FP, servo thread */
void coord_set_position(struct motmod *m, const EmcPose *pos);	/* empty queue, at rest here */
void coord_abort(struct motmod *m);	/* decelerate, then drop the queue */
void coord_clear(struct motmod *m);	/* drop the queue now (disable) */
void coord_pause(struct motmod *m);
void coord_resume(struct motmod *m);
int coord_step(struct motmod *m);	/* -EBUSY while executing */
void coord_set_term_cond(struct motmod *m, int cond, double tolerance);
/* SETUP_ARC_BLENDS (fields: motion_if.h); -EINVAL when the planner refuses a value */
int coord_set_arc_blend(struct motmod *m, const struct motion_command *c);
void coord_set_limits(struct motmod *m);	/* traj vel/acc/vel-limit/max feed scale changed */
void coord_set_spindlesync(struct motmod *m, int spindle, double units_per_rev, bool velocity_mode);
/* queue a move; 0, -ENOSPC when the queue is full, -EINVAL when the planner refuses it */
int coord_add_line(struct motmod *m, const struct motion_command *c, bool probe);
int coord_add_circle(struct motmod *m, const struct motion_command *c);
int coord_add_rigid_tap(struct motmod *m, const struct motion_command *c);
/* synchronized outputs with the next queued segment */
int coord_set_dout(struct motmod *m, int out, bool start, bool end);
int coord_set_aout(struct motmod *m, int out, double start, double end);

/* one period: the planner's world position (run once per trajectory period) and
 * every kinematic joint's interpolated command (pos_cmd, vel_cmd, coarse_pos) */
void coord_cycle(struct motmod *m, EmcPose *pos);
bool coord_is_done(struct motmod *m);	/* queue empty and stopped */
int coord_depth(struct motmod *m);
/* executing segment: line id, motion type, velocities, distance to go */
/* the planner debug parameters traj.* and tc.0..3.* (motion.md 4.1) */
void coord_debug_params(struct motmod *m);
void coord_status(struct motmod *m, rtapi_s32 *id, rtapi_s32 *motion_type, double *current_vel,
		  double *requested_vel, double *distance_to_go, int *active_depth, bool *queue_full);

#endif
