/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_rotate_fp.c - rotatekins' mathematics (kinematics.md section 4): joints 0 and 1
 * are X and Y rotated by the C coordinate; every other joint is its axis. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "kins_models.h"

void kins_rotate_inverse(const EmcPose *w, double *j)
{
	double c = w->c * KINS_DEG;
	int i;

	j[0] = w->tran.x * cos(c) - w->tran.y * sin(c);
	j[1] = w->tran.x * sin(c) + w->tran.y * cos(c);
	for (i = 2; i < KINS_NUM_AXES; i++)
		j[i] = kins_pose_get(w, i);
}

void kins_rotate_forward(const double *j, EmcPose *w)
{
	double c = -j[5] * KINS_DEG;
	int i;

	w->tran.x = j[0] * cos(c) - j[1] * sin(c);
	w->tran.y = j[0] * sin(c) + j[1] * cos(c);
	for (i = 2; i < KINS_NUM_AXES; i++)
		kins_pose_set(w, i, j[i]);
}
