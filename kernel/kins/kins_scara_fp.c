/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_scara_fp.c - scarakins' mathematics (kinematics.md section 9): shoulder j0
 * and elbow j1 about vertical axes, quill j2 (positive down), wrist j3; j4 and j5
 * carry A and B. iflags bit 0 selects the negative elbow; the forward sets it exactly
 * when the elbow is negative, so inverse(forward(j)) = j (LinuxCNC sets it for elbows
 * below 90°, which flips the arm: docs/kinematics.md). */
#include "rtapi.h"
#include "rtapi_math.h"
#include "kins_models.h"

void kins_scara_forward(const struct kins_scara *g, const double *j, EmcPose *w,
			KINEMATICS_INVERSE_FLAGS *iflags)
{
	double a0 = j[0] * KINS_DEG, a1 = (j[0] + j[1]) * KINS_DEG;
	double a3 = (j[0] + j[1] + j[3]) * KINS_DEG;

	w->tran.x = g->d2 * cos(a0) + g->d4 * cos(a1) + g->d6 * cos(a3);
	w->tran.y = g->d2 * sin(a0) + g->d4 * sin(a1) + g->d6 * sin(a3);
	w->tran.z = g->d1 + g->d3 - j[2] - g->d5;
	w->a = j[4];
	w->b = j[5];
	w->c = j[0] + j[1] + j[3];
	*iflags = j[1] < 0.0 ? KINS_SCARA_ELBOW_NEGATIVE : 0;
}

void kins_scara_inverse(const struct kins_scara *g, const EmcPose *w, double *j,
			KINEMATICS_INVERSE_FLAGS iflags)
{
	double c = w->c * KINS_DEG;
	double xt = w->tran.x - g->d6 * cos(c), yt = w->tran.y - g->d6 * sin(c);
	double cc = (xt * xt + yt * yt - g->d2 * g->d2 - g->d4 * g->d4) / (2.0 * g->d2 * g->d4);
	double q0, q1;

	/* out of reach: the arm straight (or folded) towards the target */
	if (cc > 1.0)
		cc = 1.0;
	if (cc < -1.0)
		cc = -1.0;
	q1 = acos(cc);
	if (iflags & KINS_SCARA_ELBOW_NEGATIVE)
		q1 = -q1;
	q0 = atan2(yt, xt) - atan2(g->d4 * sin(q1), g->d2 + g->d4 * cos(q1));
	j[0] = q0 / KINS_DEG;
	j[1] = q1 / KINS_DEG;
	j[2] = g->d1 + g->d3 - g->d5 - w->tran.z;
	j[3] = w->c - j[0] - j[1];
	j[4] = w->a;
	j[5] = w->b;
}
