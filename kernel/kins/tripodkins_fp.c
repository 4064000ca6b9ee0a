/* SPDX-License-Identifier: GPL-2.0-or-later */
/* tripodkins_fp.c - tripodkins' forward and inverse (kinematics.h): kins_tripod_fp.c
 * with the geometry the pins hold now. fflags: the point is below the motors' plane. */
#include "rtapi.h"
#include "kins_models.h"
#include "tripodkins.h"

void tripodkins_defaults(struct tripodkins_pins *p)
{
	*p->bx = 1.0;
	*p->cx = 1.0;
	*p->cy = 1.0;
}

static struct kins_tripod geometry(void)
{
	return (struct kins_tripod){ *tripodkins->bx, *tripodkins->cx, *tripodkins->cy };
}

static int forward(const double *joints, EmcPose *world, KINEMATICS_FORWARD_FLAGS fflags,
		   KINEMATICS_INVERSE_FLAGS *iflags)
{
	struct kins_tripod g = geometry();

	*iflags = 0;
	return kins_tripod_forward(&g, joints, world, fflags);
}

int kinematicsForward(const double *joints, EmcPose *world,
		      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	return forward(joints, world, *fflags, iflags);
}

int kinematicsInverse(const EmcPose *world, double *joints,
		      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
	struct kins_tripod g = geometry();

	return kins_tripod_inverse(&g, world, joints, fflags);
}

int kinematicsHome(EmcPose *world, double *joints,
		   KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	*fflags = 0;
	return forward(joints, world, 0, iflags);
}
