/* SPDX-License-Identifier: GPL-2.0-or-later */
/* genhexkins_fp.c - genhexkins' forward and inverse (kinematics.h): kins_genhex_fp.c
 * with the pins' values now, or the identity of coordinates= after switch type 1.
 * fflags and iflags are not used (always 0). */
#include "rtapi.h"
#include "genhexkins.h"

static void set_points(hal_float_t *(*pins)[3], const struct kins_vec *v)
{
	int n;

	for (n = 0; n < KINS_HEX_STRUTS; n++) {
		*pins[n][0] = v[n].x;
		*pins[n][1] = v[n].y;
		*pins[n][2] = v[n].z;
	}
}

static void get_points(hal_float_t *(*pins)[3], struct kins_vec *v)
{
	int n;

	for (n = 0; n < KINS_HEX_STRUTS; n++)
		v[n] = (struct kins_vec){ *pins[n][0], *pins[n][1], *pins[n][2] };
}

void genhexkins_defaults(struct genhexkins_state *s)
{
	struct kins_genhex g;

	kins_genhex_defaults(&g);
	set_points(s->base, g.base);
	set_points(s->platform, g.platform);
	set_points(s->base_n, g.base_n);
	set_points(s->platform_n, g.platform_n);
	*s->max_error = g.max_error;
	*s->criterion = g.criterion;
	*s->limit_iterations = g.limit_iterations;
}

static void geometry(struct kins_genhex *g)
{
	struct genhexkins_state *s = genhexkins;

	get_points(s->base, g->base);
	get_points(s->platform, g->platform);
	get_points(s->base_n, g->base_n);
	get_points(s->platform_n, g->platform_n);
	g->screw_lead = *s->screw_lead;
	g->z_offset = *s->spindle_offset + *s->tool_offset;
	g->max_error = *s->max_error;
	g->criterion = *s->criterion;
	g->limit_iterations = *s->limit_iterations;
}

static int forward(const double *joints, EmcPose *world, KINEMATICS_INVERSE_FLAGS *iflags)
{
	struct genhexkins_state *s = genhexkins;
	struct kins_genhex g;
	unsigned iterations;
	int err;

	*iflags = 0;
	if (s->sw.type == KINS_SWITCH_IDENTITY) {
		kins_coords_forward(&s->sw.coords, KINS_FIRST_JOINT_WINS, joints, world);
		return 0;
	}
	geometry(&g);
	err = kins_genhex_forward(&g, joints, world, &iterations);
	*s->last_iterations = iterations;
	if (iterations > *s->max_iterations)
		*s->max_iterations = iterations;
	*s->fwd_kins_fail = err != 0;
	if (!err) {
		*s->pos[0] = world->tran.x;
		*s->pos[1] = world->tran.y;
		*s->pos[2] = world->tran.z;
		*s->pos[3] = world->a;
		*s->pos[4] = world->b;
		*s->pos[5] = world->c;
	}
	return err;
}

int kinematicsForward(const double *joints, EmcPose *world,
		      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	return forward(joints, world, iflags);
}

int kinematicsInverse(const EmcPose *world, double *joints,
		      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
	struct kins_genhex g;
	double corr[KINS_HEX_STRUTS];
	int n, err;

	*fflags = 0;
	if (genhexkins->sw.type == KINS_SWITCH_IDENTITY) {
		kins_coords_inverse(&genhexkins->sw.coords, world, joints);
		return 0;
	}
	geometry(&g);
	err = kins_genhex_inverse(&g, world, joints, corr);
	for (n = 0; n < KINS_HEX_STRUTS; n++)
		*genhexkins->correction[n] = corr[n];
	return err;
}

int kinematicsHome(EmcPose *world, double *joints,
		   KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
	*fflags = 0;
	return forward(joints, world, iflags);
}
