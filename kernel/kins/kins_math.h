/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_math.h - the geometry every kinematics module shares (kins_math_fp.c): 3-vectors,
 * rotation matrices and the roll/pitch/yaw convention of kinematics.md section 1
 * (R = Rz(c)·Ry(b)·Rx(a)), rigid transforms, a small linear solver for the Newton
 * iterations of genhexkins and genserkins, and the pose as an array of nine axes.
 * HAL-free; floating point, so only *_fp.c files call it. */
#ifndef KINS_MATH_H
#define KINS_MATH_H

#include "kinematics.h"
#include "fp_split.h"

#ifdef __cplusplus
extern "C" {
#endif

#define KINS_PI 3.14159265358979323846
#define KINS_DEG (KINS_PI / 180.0)	/* radians per degree */

struct kins_vec {
	double x, y, z;
};

/* A rigid transform: rotation r (row-major, r[row][col]) then translation p. */
struct kins_frame {
	double r[3][3];
	struct kins_vec p;
};

/* The largest system kins_solve() takes. */
#define KINS_SOLVE_MAX 9

COMP_FP_LOCAL struct kins_vec kins_vec_add(struct kins_vec a, struct kins_vec b);
COMP_FP_LOCAL struct kins_vec kins_vec_sub(struct kins_vec a, struct kins_vec b);
COMP_FP_LOCAL struct kins_vec kins_vec_scale(struct kins_vec a, double k);
COMP_FP_LOCAL double kins_vec_dot(struct kins_vec a, struct kins_vec b);
COMP_FP_LOCAL struct kins_vec kins_vec_cross(struct kins_vec a, struct kins_vec b);
COMP_FP_LOCAL double kins_vec_norm(struct kins_vec a);

/* r·v, and rᵀ·v (the inverse rotation). */
COMP_FP_LOCAL struct kins_vec kins_rot_apply(const double r[3][3], struct kins_vec v);
COMP_FP_LOCAL struct kins_vec kins_rot_apply_t(const double r[3][3], struct kins_vec v);
/* out = a·b (out may not alias a or b). */
COMP_FP_LOCAL void kins_rot_mul(const double a[3][3], const double b[3][3], double out[3][3]);

/* Roll a, pitch b, yaw c in radians -> R = Rz(c)·Ry(b)·Rx(a), and back. At b = ±90°
 * the split between a and c is arbitrary: a is set to 0 there. */
COMP_FP_LOCAL void kins_rpy_to_rot(double a, double b, double c, double r[3][3]);
COMP_FP_LOCAL void kins_rot_to_rpy(const double r[3][3], double *a, double *b, double *c);

/* out = f·g (rigid transforms; out may not alias). */
COMP_FP_LOCAL void kins_frame_mul(const struct kins_frame *f, const struct kins_frame *g,
				  struct kins_frame *out);
/* The pose's position and A B C (degrees) as a frame, and back. */
COMP_FP_LOCAL void kins_pose_to_frame(const EmcPose *pose, struct kins_frame *f);
COMP_FP_LOCAL void kins_frame_to_pose(const struct kins_frame *f, EmcPose *pose);

/* The rotation vector (axis times angle, radians) of r: the rotation that takes the
 * identity to r, used as the orientation error of a Newton step. */
COMP_FP_LOCAL struct kins_vec kins_rot_to_vector(const double r[3][3]);

/* Solves a·x = b for x in place of b (n <= KINS_SOLVE_MAX; a is n×n row-major and is
 * destroyed), by Gaussian elimination with partial pivoting. 0, or -1 when a is
 * singular (a pivot below 1e-12 times the largest element). */
COMP_FP_LOCAL int kins_solve(int n, double *a, double *b);

/* Axis i (0..8 = X Y Z A B C U V W) of a pose, and setting it. */
COMP_FP_LOCAL double kins_pose_get(const EmcPose *pose, int axis);
COMP_FP_LOCAL void kins_pose_set(EmcPose *pose, int axis, double value);

#ifdef __cplusplus
}
#endif
#endif /* KINS_MATH_H */
