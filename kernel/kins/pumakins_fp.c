/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pumakins_fp.c - pumakins' forward and inverse (kinematics.h): kins_puma_fp.c with
 * the pins' values now, or the identity of coordinates= after switch type 1. */
#include "rtapi.h"
#include "kins_models.h"
#include "pumakins.h"

void pumakins_defaults(struct pumakins_state *s)
{
	*s->a2 = 300.0;
	*s->a3 = 50.0;
	*s->d3 = 70.0;
	*s->d4 = 400.0;
	*s->d6 = 70.0;
}

static struct kins_puma geometry(void)
{
	return (struct kins_puma){ *pumakins->a2, *pumakins->a3, *pumakins->d3, *pumakins->d4,
				   *pumakins->d6 };
}

static int forward(const double *joints, EmcPose *world, KINEMATICS_INVERSE_FLAGS *iflags)
{
	struct kins_puma g = geometry();

	if (pumakins->sw.type == KINS_SWITCH_IDENTITY) {
		*iflags = 0;
		kins_coords_forward(&pumakins->sw.coords, KINS_FIRST_JOINT_WINS, joints, world);
		return 0;
	}
	kins_puma_forward(&g, joints, world, iflags);
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
	struct kins_puma g = geometry();

	if (pumakins->sw.type == KINS_SWITCH_IDENTITY) {
		*fflags = 0;
		kins_coords_inverse(&pumakins->sw.coords, world, joints);
		return 0;
	}
	return kins_puma_inverse(&g, world, joints, *iflags, fflags);
}

int kinematicsHome(EmcPose *world, double *joints,
		   KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	*fflags = 0;
	*iflags = 0;
	return forward(joints, world, iflags);
}
