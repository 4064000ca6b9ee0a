/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_coords_fp.c - the identity mapping of `coordinates=` letters (kins_coords.h):
 * kinematics.md section 2.2 (first joint of a letter wins) and 3 (last joint wins). */
#include "rtapi.h"
#include "kins_coords.h"
#include "kins_math.h"

void kins_coords_forward(const struct kins_coords *c, enum kins_coords_winner w,
			 const double *joints, EmcPose *world)
{
	bool done[KINS_NUM_AXES] = { false };
	int j;

	for (j = 0; j < c->num_joints; j++) {
		int axis = c->axis[j];

		if (axis < 0 || axis >= KINS_NUM_AXES)
			continue;
		if (w == KINS_FIRST_JOINT_WINS && done[axis])
			continue;
		kins_pose_set(world, axis, joints[j]);
		done[axis] = true;
	}
}

void kins_coords_inverse(const struct kins_coords *c, const EmcPose *world, double *joints)
{
	int j;

	for (j = 0; j < c->num_joints; j++)
		if (c->axis[j] >= 0 && c->axis[j] < KINS_NUM_AXES)
			joints[j] = kins_pose_get(world, c->axis[j]);
}
