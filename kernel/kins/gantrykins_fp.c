/* SPDX-License-Identifier: GPL-2.0-or-later */
/* gantrykins_fp.c - gantrykins' forward and inverse (kinematics.h), from the
 * gantrykins.joint-N parameters as they are now (a value outside 0..8 maps nothing). */
#include "rtapi.h"
#include "gantrykins.h"

static void current_map(struct kins_coords *c)
{
	int n;

	c->num_joints = GANTRYKINS_JOINTS;
	for (n = 0; n < GANTRYKINS_JOINTS; n++) {
		rtapi_s32 axis = gantrykins->joint[n];

		c->axis[n] = (signed char)(axis >= 0 && axis < KINS_NUM_AXES ? axis : -1);
	}
}

static int forward(const double *joints, EmcPose *world)
{
	struct kins_coords c;

	current_map(&c);
	kins_coords_forward(&c, KINS_LAST_JOINT_WINS, joints, world);
	return 0;
}

int kinematicsForward(const double *joints, EmcPose *world,
		      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	return forward(joints, world);
}

int kinematicsInverse(const EmcPose *world, double *joints,
		      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
	struct kins_coords c;

	current_map(&c);
	kins_coords_inverse(&c, world, joints);
	return 0;
}

int kinematicsHome(EmcPose *world, double *joints,
		   KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	*fflags = 0;
	*iflags = 0;
	return forward(joints, world);
}
