/* SPDX-License-Identifier: GPL-2.0-or-later */
/* comp.h - backlash and leadscrew compensation of one joint (motion.md 8): the comp
 * table SET_JOINT_COMP fills, the correction it gives for a position and direction,
 * and the trapezoid filter that moves the applied correction toward it. HAL-free and
 * time-free so unit tests drive it. */
#ifndef MOTION_COMP_H
#define MOTION_COMP_H

#include "rtapi.h"
#include "motion_if.h"

#ifdef __cplusplus
extern "C" {
#endif

struct comp_point {
	double nominal;
	double fwd_trim;
	double rev_trim;
	double fwd_slope;	/* per unit of position, to the next point */
	double rev_slope;
};

/* entries [1..count] are the user's points; [0] and [count+1] bracket them at
 * -/+ a huge position with the end trims (flat extension) */
struct comp_table {
	int count;
	int pad_;
	struct comp_point pt[MOTION_COMP_SIZE + 2];
};

/* result of comp_table_add */
#define COMP_ADD_OK 0
#define COMP_ADD_FULL 1		/* "joint N: too many compensation entries" */
#define COMP_ADD_ORDER 2	/* "joint N: compensation values must increase" */
#define COMP_ADD_NOT_FINITE 3

void comp_table_clear(struct comp_table *t);
/* Append one point; type-0 files are converted by the caller (trim = nominal - actual). */
int comp_table_add(struct comp_table *t, double nominal, double fwd_trim, double rev_trim);
/* The correction at pos for a motion direction (vel > 0 forward, < 0 reverse); with
 * vel == 0 the previous correction (prev) is kept. An empty table gives
 * +-backlash/2 by direction. */
double comp_correction(const struct comp_table *t, double backlash, double pos, double vel,
		       double prev);

/* The filter: filt follows corr at most max_vel, accelerating at most max_acc
 * (motion.md 8 step 3); *vel is the filter's velocity. */
void comp_filter(double corr, double *filt, double *vel, double max_vel, double max_acc,
		 double period_s);

#ifdef __cplusplus
}
#endif
#endif
