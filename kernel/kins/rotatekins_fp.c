/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rotatekins_fp.c - rotatekins' forward and inverse (kinematics.h): kins_rotate_fp.c. */
#include "rtapi.h"
#include "kins_models.h"

int kinematicsForward(const double *joints, EmcPose *world,
		      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	kins_rotate_forward(joints, world);
	return 0;
}

int kinematicsInverse(const EmcPose *world, double *joints,
		      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
	kins_rotate_inverse(world, joints);
	return 0;
}

int kinematicsHome(EmcPose *world, double *joints,
		   KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	*fflags = 0;
	*iflags = 0;
	kins_rotate_forward(joints, world);
	return 0;
}
