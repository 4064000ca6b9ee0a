/* SPDX-License-Identifier: GPL-2.0-or-later */
/* trivkins_fp.c - trivkins' forward and inverse (kinematics.h): the coordinates=
 * mapping, the first joint of a repeated letter giving the axis its position. */
#include "rtapi.h"
#include "trivkins.h"

static int forward(const double *joints, EmcPose *world)
{
	kins_coords_forward(&trivkins.coords, KINS_FIRST_JOINT_WINS, joints, world);
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
	kins_coords_inverse(&trivkins.coords, world, joints);
	return 0;
}

int kinematicsHome(EmcPose *world, double *joints,
		   KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	*fflags = 0;
	*iflags = 0;
	return forward(joints, world);
}
