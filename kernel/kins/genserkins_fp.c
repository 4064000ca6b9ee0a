/* SPDX-License-Identifier: GPL-2.0-or-later */
/* genserkins_fp.c - genserkins' forward and inverse (kinematics.h): kins_genser_fp.c
 * with the pins' values now, or the identity of coordinates= after switch type 1. */
#include "rtapi.h"
#include "genserkins.h"

void genserkins_defaults(struct genserkins_state *s)
{
	static const double a[KINS_GENSER_LINKS] = { 0, 0, 300, 50, 0, 0 };
	static const double alpha[KINS_GENSER_LINKS] = { 0, -KINS_PI / 2, 0, -KINS_PI / 2,
							 KINS_PI / 2, -KINS_PI / 2 };
	static const double d[KINS_GENSER_LINKS] = { 0, 0, 70, 400, 0, 0 };
	int n;

	for (n = 0; n < KINS_GENSER_LINKS; n++) {
		*s->a[n] = a[n];
		*s->alpha[n] = alpha[n];
		*s->d[n] = d[n];
	}
}

static void geometry(struct kins_genser *g)
{
	int n;

	for (n = 0; n < KINS_GENSER_LINKS; n++) {
		g->a[n] = *genserkins->a[n];
		g->alpha[n] = *genserkins->alpha[n];
		g->d[n] = *genserkins->d[n];
		g->unrotate[n] = *genserkins->unrotate[n];
	}
	g->max_iterations = *genserkins->max_iterations;
}

static int forward(const double *joints, EmcPose *world, KINEMATICS_INVERSE_FLAGS *iflags)
{
	struct kins_genser g;

	*iflags = 0;
	if (genserkins->sw.type == KINS_SWITCH_IDENTITY) {
		kins_coords_forward(&genserkins->sw.coords, KINS_FIRST_JOINT_WINS, joints, world);
		return 0;
	}
	geometry(&g);
	kins_genser_forward(&g, joints, world);
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
	struct kins_genser g;
	unsigned iterations = 0;
	int err;

	*fflags = 0;
	if (genserkins->sw.type == KINS_SWITCH_IDENTITY) {
		kins_coords_inverse(&genserkins->sw.coords, world, joints);
		return 0;
	}
	geometry(&g);
	err = kins_genser_inverse(&g, world, joints, &iterations);
	*genserkins->last_iterations = iterations;
	return err;
}

int kinematicsHome(EmcPose *world, double *joints,
		   KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	*fflags = 0;
	return forward(joints, world, iflags);
}
