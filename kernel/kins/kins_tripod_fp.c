/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_tripod_fp.c - tripodkins' mathematics (kinematics.md section 5): three struts
 * from A = (0,0,0), B = (bx,0,0) and C = (cx,cy,0) to the controlled point D. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "kins_models.h"

int kins_tripod_inverse(const struct kins_tripod *g, const EmcPose *w, double *j,
			KINEMATICS_FORWARD_FLAGS *fflags)
{
	double x = w->tran.x, y = w->tran.y, z = w->tran.z;

	j[0] = sqrt(x * x + y * y + z * z);
	j[1] = sqrt((x - g->bx) * (x - g->bx) + y * y + z * z);
	j[2] = sqrt((x - g->cx) * (x - g->cx) + (y - g->cy) * (y - g->cy) + z * z);
	*fflags = z < 0.0 ? KINS_TRIPOD_BELOW : 0;
	return 0;
}

int kins_tripod_forward(const struct kins_tripod *g, const double *j, EmcPose *w,
			KINEMATICS_FORWARD_FLAGS fflags)
{
	double p, q, r, s, t, u, x, y, z2;

	if (g->bx == 0.0 || g->cy == 0.0)
		return -1;	/* A and B coincide, or A, B and C are on one line */
	/* the three sphere equations minus the first: two planes, then the first sphere */
	p = j[0] * j[0];
	q = j[1] * j[1] - g->bx * g->bx;
	r = j[2] * j[2] - g->cx * g->cx - g->cy * g->cy;
	s = -2.0 * g->bx;
	t = -2.0 * g->cx;
	u = -2.0 * g->cy;
	x = (q - p) / s;
	y = (r - q - (t - s) * x) / u;
	z2 = p - x * x - y * y;
	if (z2 < 0.0)
		return -1;	/* the lengths violate the triangle inequality */
	w->tran.x = x;
	w->tran.y = y;
	w->tran.z = fflags & KINS_TRIPOD_BELOW ? -sqrt(z2) : sqrt(z2);
	w->a = w->b = w->c = 0.0;
	return 0;
}
