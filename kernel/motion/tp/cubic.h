/* cubic.h - per-joint cubic interpolation between trajectory points (motion.md §3).
 *
 * When the trajectory period is a multiple of the servo period, motmod keeps one
 * struct cubic per joint: each time cubic_needs_next_point() is true it runs the
 * planner, converts to joint space and cubic_add_point()s the result; every servo
 * period cubic_interpolate() gives the joint command.  Way-points are
 * (x[-1] + 4 x + x[+1]) / 6, velocities (x[+1] - x[-1]) / 2T, joined by cubic
 * Hermite segments sampled `rate` times per trajectory period.  With rate 1 it
 * is a short delay line (output = planner point two cycles late, smoothed).
 *
 * Pure C, no HAL, no global state; FP (compiled in cubic_fp.c). */
#ifndef CUBIC_H
#define CUBIC_H

#ifdef __cplusplus
extern "C" {
#endif

struct cubic {
	double segment_time;	/* trajectory period T, seconds */
	double interp_time;	/* servo period, seconds */
	int rate;		/* interpolation rate = T / servo period (>= 1) */
	int filled;		/* 0: empty (first point fills all four slots) */
	int need_point;		/* cubic_needs_next_point() */
	int step;		/* sample index 0..rate-1 inside the current segment */
	double x0, x1, x2, x3;	/* the four-point queue */
	double wp0, wp1, v0, v1;	/* current Hermite segment end points and slopes */
	double a, b, c, d;	/* segment polynomial in t: a t^3 + b t^2 + c t + d */
};

/* Set periods (servo_period > 0, rate = round(traj/servo) >= 1); empties the queue. */
int cubic_init(struct cubic *cb, double traj_period, double servo_period);
/* Empty the queue: the next cubic_add_point() fills all four slots. */
void cubic_drain(struct cubic *cb);
/* Shift every stored point by delta (motmod: backlash/offset changes, kins switch). */
void cubic_offset(struct cubic *cb, double delta);
/* True when a new trajectory point must be added before cubic_interpolate(). */
int cubic_needs_next_point(const struct cubic *cb);
/* Add the next trajectory point. */
void cubic_add_point(struct cubic *cb, double point);
/* The joint command for this servo period; vel/acc may be NULL.  Returns the
 * position. */
double cubic_interpolate(struct cubic *cb, double *vel, double *acc);

#ifdef __cplusplus
}
#endif
#endif
