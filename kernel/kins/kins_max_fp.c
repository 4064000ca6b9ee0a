/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_max_fp.c - maxkins' mathematics (kinematics.md section 7): a head tilting
 * about B at pivot_length above the tool point, a table rotary C, U and W along the
 * tilted tool axis, V across it. The inverse is the documented one; the forward is
 * its exact inverse (LinuxCNC's forward is not when B and C, or B and U, are both
 * non-zero: docs/kinematics.md). Joints 3..8 are A B C U V W. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "kins_models.h"

/* The head offsets for tilt b (radians): tool point (xb, zb) from the pivot, and
 * the U travel (xv, zv) along the tilted axis. */
struct max_head {
	double xb, zb, xv, zv;
};

static struct max_head head(const struct kins_max *g, double b_deg, double u, double w)
{
	double b = b_deg * KINS_DEG, arm = g->pivot_length + w;

	return (struct max_head){ arm * sin(b), arm * cos(b), u * cos(b), u * sin(b) };
}

void kins_max_inverse(const struct kins_max *g, const EmcPose *w, double *j)
{
	struct max_head h = head(g, w->b, w->u, w->w);
	double c = w->c * KINS_DEG;
	/* the world point in the table's (rotated) frame */
	double xr = w->tran.x * cos(c) + w->tran.y * sin(c);
	double yr = w->tran.y * cos(c) - w->tran.x * sin(c);
	int i;

	if (g->conventional) {
		j[0] = xr + h.xb + h.xv;
		j[2] = w->tran.z + h.zb - h.zv - g->pivot_length;
	} else {
		j[0] = xr - h.xb + h.xv;
		j[2] = w->tran.z + h.zb + h.zv - g->pivot_length;
	}
	j[1] = yr + w->v;
	for (i = 3; i < KINS_NUM_AXES; i++)
		j[i] = kins_pose_get(w, i);
}

void kins_max_forward(const struct kins_max *g, const double *j, EmcPose *w)
{
	struct max_head h = head(g, j[4], j[6], j[8]);
	double c = j[5] * KINS_DEG, xr, yr;
	int i;

	if (g->conventional) {
		xr = j[0] - h.xb - h.xv;
		w->tran.z = j[2] - h.zb + h.zv + g->pivot_length;
	} else {
		xr = j[0] + h.xb - h.xv;
		w->tran.z = j[2] - h.zb - h.zv + g->pivot_length;
	}
	yr = j[1] - j[7];
	w->tran.x = xr * cos(c) - yr * sin(c);
	w->tran.y = xr * sin(c) + yr * cos(c);
	for (i = 3; i < KINS_NUM_AXES; i++)
		kins_pose_set(w, i, j[i]);
}
