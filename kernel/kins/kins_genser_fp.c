/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_genser_fp.c - genserkins' mathematics (kinematics.md section 10): a serial arm
 * of six revolute joints described by modified (Craig) Denavit-Hartenberg parameters.
 * Forward is the product of the link transforms; inverse is Newton's method on the
 * Jacobian, from the current joints. Joints 6..8 carry U V W. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "kins_models.h"

#define GENSER_EPSILON 1e-7	/* converged when every step is below this (radians) */

/* Link i's transform RotX(alpha)·TransX(a)·RotZ(theta)·TransZ(d), theta in radians. */
static void link_frame(const struct kins_genser *g, int i, double theta, struct kins_frame *f)
{
	double ct = cos(theta), st = sin(theta), ca = cos(g->alpha[i]), sa = sin(g->alpha[i]);

	f->r[0][0] = ct;
	f->r[0][1] = -st;
	f->r[0][2] = 0.0;
	f->r[1][0] = st * ca;
	f->r[1][1] = ct * ca;
	f->r[1][2] = -sa;
	f->r[2][0] = st * sa;
	f->r[2][1] = ct * sa;
	f->r[2][2] = ca;
	f->p = (struct kins_vec){ g->a[i], -sa * g->d[i], ca * g->d[i] };
}

/* joints (degrees) -> link angles (radians), removing the unrotate coupling */
static void joint_angles(const struct kins_genser *g, const double *j, double *q)
{
	int i;

	for (i = 0; i < KINS_GENSER_LINKS; i++)
		q[i] = (j[i] - (i > 0 ? g->unrotate[i] * j[i - 1] : 0.0)) * KINS_DEG;
}

/* The tool frame, and frames[i] = the frame of link i in base coordinates. */
static void chain(const struct kins_genser *g, const double *q, struct kins_frame *frames,
		  struct kins_frame *tool)
{
	struct kins_frame link, acc;
	int i;

	for (i = 0; i < KINS_GENSER_LINKS; i++) {
		link_frame(g, i, q[i], &link);
		if (i == 0)
			acc = link;
		else
			kins_frame_mul(&frames[i - 1], &link, &acc);
		frames[i] = acc;
	}
	*tool = frames[KINS_GENSER_LINKS - 1];
}

void kins_genser_forward(const struct kins_genser *g, const double *j, EmcPose *w)
{
	struct kins_frame frames[KINS_GENSER_LINKS], tool;
	double q[KINS_GENSER_LINKS];

	joint_angles(g, j, q);
	chain(g, q, frames, &tool);
	kins_frame_to_pose(&tool, w);
	w->u = j[6];
	w->v = j[7];
	w->w = j[8];
}

int kins_genser_inverse(const struct kins_genser *g, const EmcPose *w, double *j,
			unsigned *iterations)
{
	struct kins_frame frames[KINS_GENSER_LINKS], tool, target;
	double q[KINS_GENSER_LINKS], jac[6 * 6], err[6], rdelta[3][3];
	struct kins_vec z, col, e_rot;
	unsigned n;
	int i, k, converged;

	kins_pose_to_frame(w, &target);
	joint_angles(g, j, q);
	for (n = 1; n <= g->max_iterations; n++) {
		*iterations = n;
		chain(g, q, frames, &tool);
		/* Jacobian column i: the motion of the tool for a turn about joint i's z axis */
		for (i = 0; i < KINS_GENSER_LINKS; i++) {
			z = (struct kins_vec){ frames[i].r[0][2], frames[i].r[1][2], frames[i].r[2][2] };
			col = kins_vec_cross(z, kins_vec_sub(tool.p, frames[i].p));
			jac[0 * 6 + i] = col.x;
			jac[1 * 6 + i] = col.y;
			jac[2 * 6 + i] = col.z;
			jac[3 * 6 + i] = z.x;
			jac[4 * 6 + i] = z.y;
			jac[5 * 6 + i] = z.z;
		}
		/* the pose error in base coordinates: position, and the rotation vector of
		 * target·toolᵀ */
		for (i = 0; i < 3; i++)
			for (k = 0; k < 3; k++)
				rdelta[i][k] = target.r[i][0] * tool.r[k][0] +
					       target.r[i][1] * tool.r[k][1] +
					       target.r[i][2] * tool.r[k][2];
		e_rot = kins_rot_to_vector(rdelta);
		err[0] = target.p.x - tool.p.x;
		err[1] = target.p.y - tool.p.y;
		err[2] = target.p.z - tool.p.z;
		err[3] = e_rot.x;
		err[4] = e_rot.y;
		err[5] = e_rot.z;
		if (kins_solve(6, jac, err) < 0)
			return -1;
		converged = 1;
		for (i = 0; i < KINS_GENSER_LINKS; i++) {
			q[i] += err[i];
			if (fabs(err[i]) >= GENSER_EPSILON)
				converged = 0;
		}
		if (converged) {
			for (i = 0; i < KINS_GENSER_LINKS; i++)
				j[i] = q[i] / KINS_DEG + (i > 0 ? g->unrotate[i] * j[i - 1] : 0.0);
			j[6] = w->u;
			j[7] = w->v;
			j[8] = w->w;
			return 0;
		}
	}
	return -2;
}
