/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_puma_fp.c - pumakins' mathematics (kinematics.md section 8): a PUMA arm with
 * link parameters A2 A3 D3 D4 and a tool D6 along the last axis; joints in degrees.
 * The forward reports the arm's configuration (shoulder, elbow, wrist) in iflags;
 * the inverse picks the configuration iflags names. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "kins_models.h"

#define FUZZ 1e-6	/* how close a joint must be to a solution to be "that" solution */

/* a and b (radians) are the same angle, within FUZZ: compared modulo 2π, so that a
 * joint at 170° is recognised as the solution the inverse computes as -190°. */
static bool same_angle(double a, double b)
{
	double d = fmod(a - b, 2.0 * KINS_PI);

	if (d > KINS_PI)
		d -= 2.0 * KINS_PI;
	else if (d < -KINS_PI)
		d += 2.0 * KINS_PI;
	return fabs(d) < FUZZ;
}

void kins_puma_forward(const struct kins_puma *g, const double *j, EmcPose *w,
		       KINEMATICS_INVERSE_FLAGS *iflags)
{
	double s1 = sin(j[0] * KINS_DEG), c1 = cos(j[0] * KINS_DEG);
	double s2 = sin(j[1] * KINS_DEG), c2 = cos(j[1] * KINS_DEG);
	double s4 = sin(j[3] * KINS_DEG), c4 = cos(j[3] * KINS_DEG);
	double s5 = sin(j[4] * KINS_DEG), c5 = cos(j[4] * KINS_DEG);
	double s6 = sin(j[5] * KINS_DEG), c6 = cos(j[5] * KINS_DEG);
	double s23 = sin((j[1] + j[2]) * KINS_DEG), c23 = cos((j[1] + j[2]) * KINS_DEG);
	double t1 = c4 * c5 * c6 - s4 * s6, t1p = -c4 * c5 * s6 - s4 * c6;
	double u, v, t, sum_sq, k, w1, w2;
	struct kins_frame f;

	/* the columns of the tool rotation: x̂, ŷ, ẑ */
	u = c23 * t1 - s23 * s5 * c6;
	v = s4 * c5 * c6 + c4 * s6;
	f.r[0][0] = c1 * u + s1 * v;
	f.r[1][0] = s1 * u - c1 * v;
	f.r[2][0] = -s23 * t1 - c23 * s5 * c6;
	u = c23 * t1p + s23 * s5 * s6;
	v = c4 * c6 - s4 * c5 * s6;
	f.r[0][1] = c1 * u + s1 * v;
	f.r[1][1] = s1 * u - c1 * v;
	f.r[2][1] = -s23 * t1p + c23 * s5 * s6;
	u = c23 * c4 * s5 + s23 * c5;
	f.r[0][2] = -c1 * u - s1 * s4 * s5;
	f.r[1][2] = -s1 * u + c1 * s4 * s5;
	f.r[2][2] = s23 * c4 * s5 - c23 * c5;

	/* the wrist point */
	t = g->a2 * c2 + g->a3 * c23 - g->d4 * s23;
	f.p.x = c1 * t - g->d3 * s1;
	f.p.y = s1 * t + g->d3 * c1;
	f.p.z = -g->a3 * s23 - g->a2 * s2 - g->d4 * c23;

	/* which of the inverse's solutions these joints are */
	*iflags = 0;
	sum_sq = f.p.x * f.p.x + f.p.y * f.p.y - g->d3 * g->d3;
	k = (sum_sq + f.p.z * f.p.z - g->a2 * g->a2 - g->a3 * g->a3 - g->d4 * g->d4) / (2.0 * g->a2);
	if (same_angle(j[0] * KINS_DEG, atan2(f.p.y, f.p.x) - atan2(g->d3, -sqrt(sum_sq))))
		*iflags |= KINS_PUMA_SHOULDER_RIGHT;
	if (same_angle(j[2] * KINS_DEG, atan2(g->a3, g->d4) -
		       atan2(k, -sqrt(g->a3 * g->a3 + g->d4 * g->d4 - k * k))))
		*iflags |= KINS_PUMA_ELBOW_DOWN;
	w1 = -f.r[0][2] * s1 + f.r[1][2] * c1;
	w2 = -f.r[0][2] * c1 * c23 - f.r[1][2] * s1 * c23 + f.r[2][2] * s23;
	if (fabs(w1) < FUZZ && fabs(w2) < FUZZ)
		*iflags |= KINS_PUMA_SINGULAR;
	else if (!same_angle(j[3] * KINS_DEG, atan2(w1, w2)))
		*iflags |= KINS_PUMA_WRIST_FLIP;

	/* the tool point is D6 along ẑ */
	f.p.x += g->d6 * f.r[0][2];
	f.p.y += g->d6 * f.r[1][2];
	f.p.z += g->d6 * f.r[2][2];
	kins_frame_to_pose(&f, w);
}

int kins_puma_inverse(const struct kins_puma *g, const EmcPose *w, double *j,
		      KINEMATICS_INVERSE_FLAGS iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
	struct kins_frame f;
	double px, py, pz, sum_sq, k, r, th1, th3, th23, th4, th5, th6;
	double s1, c1, s3, c3, s23, c23, s4, c4, s5, c5, s6, c6, t1, t2, t3, w1, w2;
	double (*m)[3];

	kins_pose_to_frame(w, &f);
	m = f.r;
	/* the wrist point: D6 back along ẑ */
	px = f.p.x - g->d6 * m[0][2];
	py = f.p.y - g->d6 * m[1][2];
	pz = f.p.z - g->d6 * m[2][2];
	*fflags = 0;

	sum_sq = px * px + py * py - g->d3 * g->d3;
	r = sqrt(sum_sq);	/* NaN out of reach: motion reports the non-finite joint */
	th1 = atan2(py, px) - atan2(g->d3, iflags & KINS_PUMA_SHOULDER_RIGHT ? -r : r);
	s1 = sin(th1);
	c1 = cos(th1);

	k = (sum_sq + pz * pz - g->a2 * g->a2 - g->a3 * g->a3 - g->d4 * g->d4) / (2.0 * g->a2);
	r = sqrt(g->a3 * g->a3 + g->d4 * g->d4 - k * k);
	th3 = atan2(g->a3, g->d4) - atan2(k, iflags & KINS_PUMA_ELBOW_DOWN ? -r : r);
	s3 = sin(th3);
	c3 = cos(th3);

	t1 = (-g->a3 - g->a2 * c3) * pz + (c1 * px + s1 * py) * (g->a2 * s3 - g->d4);
	t2 = (g->a2 * s3 - g->d4) * pz + (g->a3 + g->a2 * c3) * (c1 * px + s1 * py);
	t3 = pz * pz + (c1 * px + s1 * py) * (c1 * px + s1 * py);
	th23 = atan2(t1, t2);
	s23 = t1 / t3;
	c23 = t2 / t3;

	w1 = -m[0][2] * s1 + m[1][2] * c1;
	w2 = -m[0][2] * c1 * c23 - m[1][2] * s1 * c23 + m[2][2] * s23;
	if (fabs(w1) < FUZZ && fabs(w2) < FUZZ) {
		/* θ5 = 0: only θ4 + θ6 is defined; keep joint 3 where it is */
		th4 = j[3] * KINS_DEG;
		*fflags |= KINS_PUMA_REACH;
	} else {
		th4 = atan2(w1, w2);
	}
	s4 = sin(th4);
	c4 = cos(th4);

	s5 = m[2][2] * s23 * c4 - m[0][2] * (c1 * c23 * c4 + s1 * s4) -
	     m[1][2] * (s1 * c23 * c4 - c1 * s4);
	c5 = -m[0][2] * c1 * s23 - m[1][2] * s1 * s23 - m[2][2] * c23;
	th5 = atan2(s5, c5);

	s6 = m[2][0] * s23 * s4 - m[0][0] * (c1 * c23 * s4 - s1 * c4) -
	     m[1][0] * (s1 * c23 * s4 + c1 * c4);
	c6 = m[0][0] * ((c1 * c23 * c4 + s1 * s4) * c5 - c1 * s23 * s5) +
	     m[1][0] * ((s1 * c23 * c4 - c1 * s4) * c5 - s1 * s23 * s5) -
	     m[2][0] * (s23 * c4 * c5 + c23 * s5);
	th6 = atan2(s6, c6);

	if (iflags & KINS_PUMA_WRIST_FLIP) {
		th4 += KINS_PI;
		th5 = -th5;
		th6 += KINS_PI;
	}
	j[0] = th1 / KINS_DEG;
	j[1] = (th23 - th3) / KINS_DEG;
	j[2] = th3 / KINS_DEG;
	j[3] = th4 / KINS_DEG;
	j[4] = th5 / KINS_DEG;
	j[5] = th6 / KINS_DEG;
	return 0;
}
