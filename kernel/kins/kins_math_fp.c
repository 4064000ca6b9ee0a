/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_math_fp.c - vectors, rotations, rigid transforms and a linear solver shared by
 * the kinematics modules (kins_math.h). Floating point only. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "kins_math.h"

struct kins_vec kins_vec_add(struct kins_vec a, struct kins_vec b)
{
	return (struct kins_vec){ a.x + b.x, a.y + b.y, a.z + b.z };
}

struct kins_vec kins_vec_sub(struct kins_vec a, struct kins_vec b)
{
	return (struct kins_vec){ a.x - b.x, a.y - b.y, a.z - b.z };
}

struct kins_vec kins_vec_scale(struct kins_vec a, double k)
{
	return (struct kins_vec){ a.x * k, a.y * k, a.z * k };
}

double kins_vec_dot(struct kins_vec a, struct kins_vec b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}

struct kins_vec kins_vec_cross(struct kins_vec a, struct kins_vec b)
{
	return (struct kins_vec){ a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
				  a.x * b.y - a.y * b.x };
}

double kins_vec_norm(struct kins_vec a)
{
	return sqrt(kins_vec_dot(a, a));
}

struct kins_vec kins_rot_apply(const double r[3][3], struct kins_vec v)
{
	return (struct kins_vec){ r[0][0] * v.x + r[0][1] * v.y + r[0][2] * v.z,
				  r[1][0] * v.x + r[1][1] * v.y + r[1][2] * v.z,
				  r[2][0] * v.x + r[2][1] * v.y + r[2][2] * v.z };
}

struct kins_vec kins_rot_apply_t(const double r[3][3], struct kins_vec v)
{
	return (struct kins_vec){ r[0][0] * v.x + r[1][0] * v.y + r[2][0] * v.z,
				  r[0][1] * v.x + r[1][1] * v.y + r[2][1] * v.z,
				  r[0][2] * v.x + r[1][2] * v.y + r[2][2] * v.z };
}

void kins_rot_mul(const double a[3][3], const double b[3][3], double out[3][3])
{
	int i, j;

	for (i = 0; i < 3; i++)
		for (j = 0; j < 3; j++)
			out[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
}

void kins_rpy_to_rot(double a, double b, double c, double r[3][3])
{
	double sa = sin(a), ca = cos(a), sb = sin(b), cb = cos(b), sc = sin(c), cc = cos(c);

	r[0][0] = cc * cb;
	r[0][1] = cc * sb * sa - sc * ca;
	r[0][2] = cc * sb * ca + sc * sa;
	r[1][0] = sc * cb;
	r[1][1] = sc * sb * sa + cc * ca;
	r[1][2] = sc * sb * ca - cc * sa;
	r[2][0] = -sb;
	r[2][1] = cb * sa;
	r[2][2] = cb * ca;
}

void kins_rot_to_rpy(const double r[3][3], double *a, double *b, double *c)
{
	double cb = sqrt(r[0][0] * r[0][0] + r[1][0] * r[1][0]);

	*b = atan2(-r[2][0], cb);
	if (cb < 1e-12) {
		/* gimbal lock: only c - a (b = +90°) or c + a (b = -90°) is defined */
		*a = 0.0;
		*c = atan2(-r[0][1], r[1][1]);
	} else {
		*a = atan2(r[2][1], r[2][2]);
		*c = atan2(r[1][0], r[0][0]);
	}
}

void kins_frame_mul(const struct kins_frame *f, const struct kins_frame *g, struct kins_frame *out)
{
	kins_rot_mul(f->r, g->r, out->r);
	out->p = kins_vec_add(kins_rot_apply(f->r, g->p), f->p);
}

void kins_pose_to_frame(const EmcPose *pose, struct kins_frame *f)
{
	kins_rpy_to_rot(pose->a * KINS_DEG, pose->b * KINS_DEG, pose->c * KINS_DEG, f->r);
	f->p = (struct kins_vec){ pose->tran.x, pose->tran.y, pose->tran.z };
}

void kins_frame_to_pose(const struct kins_frame *f, EmcPose *pose)
{
	double a, b, c;

	kins_rot_to_rpy(f->r, &a, &b, &c);
	pose->tran.x = f->p.x;
	pose->tran.y = f->p.y;
	pose->tran.z = f->p.z;
	pose->a = a / KINS_DEG;
	pose->b = b / KINS_DEG;
	pose->c = c / KINS_DEG;
}

struct kins_vec kins_rot_to_vector(const double r[3][3])
{
	struct kins_vec axis = { r[2][1] - r[1][2], r[0][2] - r[2][0], r[1][0] - r[0][1] };
	double s2 = kins_vec_norm(axis);		/* 2 sin(angle) */
	double c2 = r[0][0] + r[1][1] + r[2][2] - 1.0;	/* 2 cos(angle) */
	double angle = atan2(s2, c2);
	struct kins_vec col, best = { 0.0, 0.0, 0.0 };
	double n, bestn = -1.0;
	int i;

	if (s2 >= 1e-9)
		return kins_vec_scale(axis, angle / s2);
	if (c2 > 0.0)
		return best;	/* no rotation */
	/* a half turn: r + I = 2·axis·axisᵀ, so its largest column is along the axis */
	for (i = 0; i < 3; i++) {
		col = (struct kins_vec){ r[0][i] + (i == 0), r[1][i] + (i == 1), r[2][i] + (i == 2) };
		n = kins_vec_dot(col, col);
		if (n > bestn) {
			bestn = n;
			best = col;
		}
	}
	return kins_vec_scale(best, angle / sqrt(bestn));
}

int kins_solve(int n, double *a, double *b)
{
	double big = 0.0, t;
	int i, j, k, p;

	if (n < 1 || n > KINS_SOLVE_MAX)
		return -1;
	for (i = 0; i < n * n; i++)
		if (fabs(a[i]) > big)
			big = fabs(a[i]);
	if (big == 0.0)
		return -1;
	for (k = 0; k < n; k++) {
		p = k;
		for (i = k + 1; i < n; i++)
			if (fabs(a[i * n + k]) > fabs(a[p * n + k]))
				p = i;
		if (fabs(a[p * n + k]) < 1e-12 * big)
			return -1;
		if (p != k) {
			for (j = 0; j < n; j++) {
				t = a[k * n + j];
				a[k * n + j] = a[p * n + j];
				a[p * n + j] = t;
			}
			t = b[k];
			b[k] = b[p];
			b[p] = t;
		}
		for (i = k + 1; i < n; i++) {
			t = a[i * n + k] / a[k * n + k];
			for (j = k; j < n; j++)
				a[i * n + j] -= t * a[k * n + j];
			b[i] -= t * b[k];
		}
	}
	for (i = n - 1; i >= 0; i--) {
		t = b[i];
		for (j = i + 1; j < n; j++)
			t -= a[i * n + j] * b[j];
		b[i] = t / a[i * n + i];
	}
	return 0;
}

double kins_pose_get(const EmcPose *pose, int axis)
{
	switch (axis) {
	case 0: return pose->tran.x;
	case 1: return pose->tran.y;
	case 2: return pose->tran.z;
	case 3: return pose->a;
	case 4: return pose->b;
	case 5: return pose->c;
	case 6: return pose->u;
	case 7: return pose->v;
	default: return pose->w;
	}
}

void kins_pose_set(EmcPose *pose, int axis, double value)
{
	switch (axis) {
	case 0: pose->tran.x = value; break;
	case 1: pose->tran.y = value; break;
	case 2: pose->tran.z = value; break;
	case 3: pose->a = value; break;
	case 4: pose->b = value; break;
	case 5: pose->c = value; break;
	case 6: pose->u = value; break;
	case 7: pose->v = value; break;
	default: pose->w = value; break;
	}
}
