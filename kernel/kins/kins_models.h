/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_models.h - the HAL-free mathematics of each kinematics module, with its
 * geometry as an argument: kins_<model>_fp.c implement kinematics.md sections 4-10.
 * The modules (<name>kins_fp.c) copy their HAL pins into these structs and call
 * these functions; the unit tests (tests/unit/kinematics) call the same ones.
 * Floating point: call only from *_fp.c code. Joints and angles in degrees where
 * the module's page says so. Each returns 0 or a negative value as kinematics.h's
 * kinematicsForward/kinematicsInverse. */
#ifndef KINS_MODELS_H
#define KINS_MODELS_H

#include "kinematics.h"
#include "kins_math.h"

#ifdef __cplusplus
extern "C" {
#endif

/* rotatekins (section 4): 9 joints, table frame rotated by C. */
COMP_FP_LOCAL void kins_rotate_forward(const double *j, EmcPose *w);
COMP_FP_LOCAL void kins_rotate_inverse(const EmcPose *w, double *j);

/* tripodkins (section 5): strut lengths from (0,0,0), (bx,0,0), (cx,cy,0). */
struct kins_tripod {
	double bx, cx, cy;
};
#define KINS_TRIPOD_BELOW 1UL	/* fflags: the point is below the plane of the motors */
COMP_FP_LOCAL int kins_tripod_forward(const struct kins_tripod *g, const double *j, EmcPose *w,
				      KINEMATICS_FORWARD_FLAGS fflags);
COMP_FP_LOCAL int kins_tripod_inverse(const struct kins_tripod *g, const EmcPose *w, double *j,
				      KINEMATICS_FORWARD_FLAGS *fflags);

/* maxkins (section 7): tilting head B, table rotary C. The forward is the exact
 * inverse of the inverse (see docs/kinematics.md). */
struct kins_max {
	double pivot_length;
	bool conventional;	/* 2.10 conventional-directions */
};
COMP_FP_LOCAL void kins_max_forward(const struct kins_max *g, const double *j, EmcPose *w);
COMP_FP_LOCAL void kins_max_inverse(const struct kins_max *g, const EmcPose *w, double *j);

/* scarakins (section 9): 6 joints (j4, j5 carry A, B). iflags bit 0: elbow negative. */
struct kins_scara {
	double d1, d2, d3, d4, d5, d6;
};
#define KINS_SCARA_ELBOW_NEGATIVE 1UL
COMP_FP_LOCAL void kins_scara_forward(const struct kins_scara *g, const double *j, EmcPose *w,
				      KINEMATICS_INVERSE_FLAGS *iflags);
COMP_FP_LOCAL void kins_scara_inverse(const struct kins_scara *g, const EmcPose *w, double *j,
				      KINEMATICS_INVERSE_FLAGS iflags);

/* pumakins (section 8): 6 joints. */
struct kins_puma {
	double a2, a3, d3, d4, d6;
};
#define KINS_PUMA_SHOULDER_RIGHT 0x01UL	/* iflags */
#define KINS_PUMA_ELBOW_DOWN 0x02UL
#define KINS_PUMA_WRIST_FLIP 0x04UL
#define KINS_PUMA_SINGULAR 0x08UL
#define KINS_PUMA_REACH 0x01UL		/* fflags: the wrist was singular, joint 3 kept */
COMP_FP_LOCAL void kins_puma_forward(const struct kins_puma *g, const double *j, EmcPose *w,
				     KINEMATICS_INVERSE_FLAGS *iflags);
COMP_FP_LOCAL int kins_puma_inverse(const struct kins_puma *g, const EmcPose *w, double *j,
				    KINEMATICS_INVERSE_FLAGS iflags, KINEMATICS_FORWARD_FLAGS *fflags);

/* genserkins (section 10): 6 revolute joints (modified DH), joints 6..8 = U V W. */
#define KINS_GENSER_LINKS 6
struct kins_genser {
	double a[KINS_GENSER_LINKS], alpha[KINS_GENSER_LINKS], d[KINS_GENSER_LINKS];
	int unrotate[KINS_GENSER_LINKS];
	unsigned max_iterations;
};
COMP_FP_LOCAL void kins_genser_forward(const struct kins_genser *g, const double *j, EmcPose *w);
/* Starts from j[] (the current joints); *iterations = Newton steps taken. -1 when the
 * Jacobian is singular, -2 when max_iterations pass without convergence. */
COMP_FP_LOCAL int kins_genser_inverse(const struct kins_genser *g, const EmcPose *w, double *j,
				      unsigned *iterations);

/* genhexkins (section 6): 6 struts between base points and platform points. */
#define KINS_HEX_STRUTS 6
struct kins_genhex {
	struct kins_vec base[KINS_HEX_STRUTS], platform[KINS_HEX_STRUTS];
	struct kins_vec base_n[KINS_HEX_STRUTS], platform_n[KINS_HEX_STRUTS];
	double screw_lead;	/* 0: no correction */
	double z_offset;	/* spindle-offset + tool-offset, added to every point's z */
	double max_error, criterion;
	unsigned limit_iterations;
};
/* Strut lengths of pose w; corr[i] (may be NULL) receives the screw correction. */
COMP_FP_LOCAL int kins_genhex_inverse(const struct kins_genhex *g, const EmcPose *w, double *j,
				      double *corr);
/* Newton from *w. *iterations = steps taken. -1: a joint <= 0 or a zero-length strut;
 * -2: the error grew past max_error; -5: limit_iterations passed; -3: singular. */
COMP_FP_LOCAL int kins_genhex_forward(const struct kins_genhex *g, const double *j, EmcPose *w,
				      unsigned *iterations);
/* The default geometry (kinematics.md 6.1), offsets and screw lead 0. */
COMP_FP_LOCAL void kins_genhex_defaults(struct kins_genhex *g);

#ifdef __cplusplus
}
#endif
#endif /* KINS_MODELS_H */
