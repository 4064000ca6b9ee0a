/* SPDX-License-Identifier: GPL-2.0-or-later */
/* scarakins_fp.c - scarakins' forward and inverse (kinematics.h): kins_scara_fp.c
 * with the pins' values now, or the identity of coordinates= after switch type 1. */
#include "rtapi.h"
#include "kins_models.h"
#include "scarakins.h"

void scarakins_defaults(struct scarakins_state *s)
{
	static const double d[6] = { 490, 340, 50, 250, 50, 50 };
	int i;

	for (i = 0; i < 6; i++)
		*s->d[i] = d[i];
}

static struct kins_scara geometry(void)
{
	return (struct kins_scara){ *scarakins->d[0], *scarakins->d[1], *scarakins->d[2],
				    *scarakins->d[3], *scarakins->d[4], *scarakins->d[5] };
}

static int forward(const double *joints, EmcPose *world, KINEMATICS_INVERSE_FLAGS *iflags)
{
	struct kins_scara g = geometry();

	if (scarakins->sw.type == KINS_SWITCH_IDENTITY) {
		*iflags = 0;
		kins_coords_forward(&scarakins->sw.coords, KINS_FIRST_JOINT_WINS, joints, world);
		return 0;
	}
	kins_scara_forward(&g, joints, world, iflags);
	return 0;
}

int kinematicsForward(const double *joints, EmcPose *world,
		      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	return forward(joints, world, iflags);
}

int kinematicsInverse(const EmcPose *world, double *joints,
		      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
	struct kins_scara g = geometry();

	*fflags = 0;
	if (scarakins->sw.type == KINS_SWITCH_IDENTITY)
		kins_coords_inverse(&scarakins->sw.coords, world, joints);
	else
		kins_scara_inverse(&g, world, joints, *iflags);
	return 0;
}

int kinematicsHome(EmcPose *world, double *joints,
		   KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	*fflags = 0;
	*iflags = 0;
	return forward(joints, world, iflags);
}
