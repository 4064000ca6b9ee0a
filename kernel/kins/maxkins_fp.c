/* SPDX-License-Identifier: GPL-2.0-or-later */
/* maxkins_fp.c - maxkins' forward and inverse (kinematics.h): kins_max_fp.c with the
 * pins' values now. */
#include "rtapi.h"
#include "kins_models.h"
#include "maxkins.h"

void maxkins_defaults(struct maxkins_pins *p)
{
	*p->pivot_length = 0.666;
}

static struct kins_max geometry(void)
{
	return (struct kins_max){ *maxkins->pivot_length, *maxkins->conventional };
}

int kinematicsForward(const double *joints, EmcPose *world,
		      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	struct kins_max g = geometry();

	kins_max_forward(&g, joints, world);
	return 0;
}

int kinematicsInverse(const EmcPose *world, double *joints,
		      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
	struct kins_max g = geometry();

	kins_max_inverse(&g, world, joints);
	return 0;
}

int kinematicsHome(EmcPose *world, double *joints,
		   KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	struct kins_max g = geometry();

	*fflags = 0;
	*iflags = 0;
	kins_max_forward(&g, joints, world);
	return 0;
}
