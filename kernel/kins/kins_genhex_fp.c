/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_genhex_fp.c - genhexkins' mathematics (kinematics.md section 6): a Stewart
 * platform, six struts from base points b_i to platform points a_i. Inverse: the
 * strut lengths |P + R·a_i − b_i| (plus the screw correction of non-captive screws);
 * forward: Newton's method on the inverse Jacobian, from the pose passed in. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "kins_models.h"

static const double default_base[KINS_HEX_STRUTS][3] = {
	{ -22.950, 13.250, 0 }, { 22.950, 13.250, 0 }, { 22.950, 13.250, 0 },
	{ 0, -26.500, 0 }, { 0, -26.500, 0 }, { -22.950, 13.250, 0 },
};
static const double default_platform[KINS_HEX_STRUTS][3] = {
	{ -1.000, 11.500, 0 }, { 1.000, 11.500, 0 }, { 10.459, -4.884, 0 },
	{ 9.459, -6.616, 0 }, { -9.459, -6.616, 0 }, { -10.459, -4.884, 0 },
};
static const double default_base_n[KINS_HEX_STRUTS][3] = {
	{ 0.707107, 0, 0.707107 }, { 0, -0.707107, 0.707107 }, { -0.707107, 0, 0.707107 },
	{ -0.707107, 0, 0.707107 }, { 0, 0.707107, 0.707107 }, { 0.707107, 0, 0.707107 },
};
static const double default_platform_n[KINS_HEX_STRUTS][3] = {
	{ -1, 0, 0 }, { 0.866025, 0.5, 0 }, { 0.866025, 0.5, 0 },
	{ 0.866025, -0.5, 0 }, { 0.866025, -0.5, 0 }, { -1, 0, 0 },
};

static struct kins_vec vec3(const double v[3])
{
	return (struct kins_vec){ v[0], v[1], v[2] };
}

void kins_genhex_defaults(struct kins_genhex *g)
{
	int i;

	for (i = 0; i < KINS_HEX_STRUTS; i++) {
		g->base[i] = vec3(default_base[i]);
		g->platform[i] = vec3(default_platform[i]);
		g->base_n[i] = vec3(default_base_n[i]);
		g->platform_n[i] = vec3(default_platform_n[i]);
	}
	g->screw_lead = 0.0;
	g->z_offset = 0.0;
	g->max_error = 500.0;
	g->criterion = 1e-9;
	g->limit_iterations = 120;
}

/* Strut i at position p and rotation r: its vector (base to platform), the platform
 * point in world orientation (r·a_i), and its length including the correction. */
struct strut {
	struct kins_vec v, ra;
	double length, corr;
};

static struct strut strut_at(const struct kins_genhex *g, int i, struct kins_vec p,
			     const double r[3][3])
{
	struct kins_vec off = { 0.0, 0.0, g->z_offset };
	struct kins_vec b = kins_vec_add(g->base[i], off), a = kins_vec_add(g->platform[i], off);
	struct kins_vec u, nb3, na2;
	struct strut s;
	double n;

	s.ra = kins_rot_apply(r, a);
	s.v = kins_vec_sub(kins_vec_add(p, s.ra), b);
	s.length = kins_vec_norm(s.v);
	s.corr = 0.0;
	if (g->screw_lead != 0.0 && s.length > 0.0) {
		/* a non-captive screw turned by the cardan joints' twist */
		u = kins_vec_scale(s.v, 1.0 / s.length);
		nb3 = kins_vec_cross(u, kins_vec_cross(g->base_n[i], u));
		n = kins_vec_norm(nb3);
		nb3 = n > 0.0 ? kins_vec_scale(nb3, 1.0 / n) : nb3;
		na2 = kins_vec_cross(kins_rot_apply(r, g->platform_n[i]), u);
		n = kins_vec_norm(na2);
		na2 = n > 0.0 ? kins_vec_scale(na2, 1.0 / n) : na2;
		s.corr = g->screw_lead * asin(kins_vec_dot(nb3, na2)) / (2.0 * KINS_PI);
	}
	s.length += s.corr;
	return s;
}

int kins_genhex_inverse(const struct kins_genhex *g, const EmcPose *w, double *j, double *corr)
{
	struct kins_frame f;
	struct strut s;
	int i;

	kins_pose_to_frame(w, &f);
	for (i = 0; i < KINS_HEX_STRUTS; i++) {
		s = strut_at(g, i, f.p, f.r);
		j[i] = s.length;
		if (corr)
			corr[i] = s.corr;
	}
	return 0;
}

int kins_genhex_forward(const struct kins_genhex *g, const double *j, EmcPose *w,
			unsigned *iterations)
{
	double a = w->a * KINS_DEG, b = w->b * KINS_DEG, c = w->c * KINS_DEG;
	struct kins_vec p = { w->tran.x, w->tran.y, w->tran.z }, u, m;
	double r[3][3], jac[6 * 6], diff[6], conv_err;
	struct strut s;
	unsigned n;
	int i, done;

	*iterations = 0;
	for (i = 0; i < KINS_HEX_STRUTS; i++)
		if (j[i] <= 0.0)
			return -1;
	for (n = 1;; n++) {
		*iterations = n;
		if (n > g->limit_iterations)
			return -5;
		kins_rpy_to_rot(a, b, c, r);
		conv_err = 0.0;
		done = 1;
		for (i = 0; i < KINS_HEX_STRUTS; i++) {
			s = strut_at(g, i, p, r);
			if (s.length - s.corr <= 0.0)
				return -1;
			u = kins_vec_scale(s.v, 1.0 / (s.length - s.corr));
			m = kins_vec_cross(s.ra, u);
			jac[i * 6 + 0] = u.x;
			jac[i * 6 + 1] = u.y;
			jac[i * 6 + 2] = u.z;
			jac[i * 6 + 3] = m.x;
			jac[i * 6 + 4] = m.y;
			jac[i * 6 + 5] = m.z;
			diff[i] = s.length - j[i];
			conv_err += fabs(diff[i]);
			if (fabs(diff[i]) > g->criterion)
				done = 0;
		}
		if (done)
			break;
		if (conv_err > g->max_error)
			return -2;
		if (kins_solve(6, jac, diff) < 0)
			return -3;
		p = kins_vec_sub(p, (struct kins_vec){ diff[0], diff[1], diff[2] });
		a -= diff[3];
		b -= diff[4];
		c -= diff[5];
	}
	w->tran.x = p.x;
	w->tran.y = p.y;
	w->tran.z = p.z;
	w->a = a / KINS_DEG;
	w->b = b / KINS_DEG;
	w->c = c / KINS_DEG;
	return 0;
}
