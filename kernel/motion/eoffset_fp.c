/* SPDX-License-Identifier: GPL-2.0-or-later */
/* eoffset_fp.c - external offsets (motion.md 4.2 axis.L.eoffset-*, 3 step 13): per
 * axis, axis.L.eoffset-counts x eoffset-scale while eoffset-enable is TRUE (counts
 * turned while it is FALSE are dropped; eoffset-clear asks for 0), reached by a
 * trapezoid planner at the axis' external-offset velocity and acceleration
 * (SET_AXIS_EXT_OFFSET_LIMITS: task's [AXIS_L]OFFSET_AV_RATIO share; 0 = no external
 * offset on that axis), and added to the world command before the inverse kinematics
 * in TELEOP and COORD. The offset is clipped so the axis stays inside its position
 * limits (motion.eoffset-limited). Outside TELEOP/COORD there is no offset: leaving
 * them keeps the joints where they are (the offset becomes part of the position) and
 * the count register starts again from the counts at that time. */
#include "motmod_priv.h"

void mot_eoffset_update(struct motmod *m)
{
	bool on = m->state == MOTION_TELEOP || m->state == MOTION_COORD;
	double world[MOTION_MAX_AXES];
	int l;

	mot_pose_to_array(&m->world_cmd, world);
	m->eoffset_limited = false;
	for (l = 0; l < MOTION_MAX_AXES; l++) {
		struct mot_axis *ax = &m->axis[l];
		struct mot_axis_pins *ap = &m->pins->axis[l];
		rtapi_s32 counts = *ap->eoffset_counts;
		double target;

		if (!on || ax->eoff_vel <= 0.0 || ax->eoff_acc <= 0.0) {
			ax->eoff_old_counts = counts;
			ax->eoff_request = 0.0;
			freetp_reset(&ax->eoff, 0.0);
			continue;
		}
		if (*ap->eoffset_clear)
			ax->eoff_request = 0.0;
		else if (*ap->eoffset_enable)
			ax->eoff_request += (double)(counts - ax->eoff_old_counts) * *ap->eoffset_scale;
		ax->eoff_old_counts = counts;
		target = ax->eoff_request;
		if (world[l] + target > ax->max_limit) {
			target = ax->max_limit - world[l];
			m->eoffset_limited = true;
		} else if (world[l] + target < ax->min_limit) {
			target = ax->min_limit - world[l];
			m->eoffset_limited = true;
		}
		ax->eoff.pos_cmd = target;
		ax->eoff.max_vel = ax->eoff_vel;
		ax->eoff.max_acc = ax->eoff_acc;
		ax->eoff.enable = true;
		freetp_update(&ax->eoff, m->servo_period_s);
	}
}

void mot_eoffset_add(const struct motmod *m, EmcPose *world)
{
	double v[MOTION_MAX_AXES];
	int l;

	mot_pose_to_array(world, v);
	for (l = 0; l < MOTION_MAX_AXES; l++)
		v[l] += m->axis[l].eoff.curr_pos;
	mot_array_to_pose(v, world);
}

bool mot_eoffset_moving(const struct motmod *m)
{
	int l;

	for (l = 0; l < MOTION_MAX_AXES; l++)
		if (m->axis[l].eoff.active)
			return true;
	return false;
}
