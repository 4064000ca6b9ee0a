/* tp_internal.h - the planner's records, shared by its *_fp.c units only.
 * motmod sees struct tp as opaque (tp.h).  Layout: struct tp, then the segment
 * ring of tp->size struct tc records, in one caller-provided block. */
#ifndef TP_INTERNAL_H
#define TP_INTERNAL_H

#include "tp.h"

#define TP_N TP_NUM_AXES
#define TP_PI 3.14159265358979323846
#define TP_BIG 1e99		/* "no limit" */
#define TP_EPS 1e-12		/* lengths below this are zero */
#define TP_ADD_MARGIN 2		/* free slots a new segment needs: itself + a blend arc */

enum tc_kind {
	TC_LINE,		/* straight move in 9D, length metric of §10.1 */
	TC_CIRCLE,		/* helix/spiral in XYZ + linear ABC UVW */
	TC_BLEND,		/* circular blend arc in the plane of two lines (9D) */
	TC_TAP,			/* rigid tap: in and out along a line, spindle-synchronized */
};

enum tap_phase {
	TAP_TAPPING, TAP_REVERSING, TAP_RETRACTION, TAP_FINAL_REVERSAL, TAP_FINAL_PLACEMENT,
};

/* One queued segment.  Written by the tp_add_* functions (command handler) and by
 * tp_run_cycle (run-time fields); both run in motmod's servo thread. */
struct tc {
	int kind;			/* enum tc_kind */
	double start[TP_N], end[TP_N];
	double len;			/* path length (target of progress) */
	double nominal_len;		/* length as programmed, before blend trims */
	double progress;		/* distance travelled along the path */
	/* line / tap: unit-path direction dpos/ds (|dir| may exceed 1 for mixed moves) */
	double dir[TP_N];
	/* circle: helix around axis n through centre c; abc/uvw linear in the fraction */
	double c[3], n[3], e1[3], e2[3];
	double r0, dr, h0, dh, angle;
	/* blend arc (9D): centre + R (cos phi b1 + sin phi b2), phi in [0, angle] */
	double bc[TP_N], b1[TP_N], b2[TP_N], br;
	/* limits */
	double reqvel;			/* requested velocity (F) */
	double maxvel;			/* kinematic bound incl. arc/blend normal-acceleration bound */
	double acc;			/* tangential acceleration allowed (incl. halving) */
	double vf;			/* look-ahead exit velocity (tangent junctions) */
	double kink_vel;		/* bound at the junction to the next segment */
	int term;			/* enum tp_term_cond resolved for the junction to the next */
	int blend_next;			/* parabolic overlap with the next segment */
	double blend_tol;		/* tolerance of the parabolic blend (0 = none) */
	double blend_cos;		/* cos(theta) of that junction, theta = half angle */
	int pure_rotary;		/* only ABC move: vlimit does not apply */
	int linear_group;		/* line: 0 XYZ, 1 UVW, 2 ABC length metric, -1 mixed */
	/* identity */
	int motion_type, id, tag, atspeed, probe_type;
	unsigned char enables;
	/* spindle synchronisation */
	int sync;			/* enum tp_sync_mode */
	int spindle_num;
	double uu_per_rev;
	/* rigid tap */
	int tap_phase;
	double tap_x;			/* signed position along dir from start */
	double tap_scale;		/* reversal scale */
	double tap_revs_prev;
	double tap_x0;			/* final placement starts here */
	/* synchronized outputs at segment start, and the changed ones at its end */
	rtapi_u64 dout_mask, dout_value, dout_end_mask, dout_end_value;
	int aout_count;
	struct tp_aout aout[TP_SEG_AIO_MAX];
	/* run time */
	int active;			/* has started moving (outputs emitted) */
	double vel;			/* current path speed */
	double blend_start_vel;		/* parabolic: sum speed kept during the overlap */
	int blending_in;		/* prev blends into this one (parabolic overlap) */
	int overlap;			/* moving as the second half of a parabolic overlap */
	int decel;			/* last update was limited by the stopping distance */
};

struct tp {
	int size;			/* ring capacity */
	int head, count;		/* head = executing segment, count queued */
	double cycle;			/* seconds */
	double vmax, ini_maxvel;	/* SET_VEL (kept for status / defaults) */
	double vlimit, amax;		/* SET_VEL_LIMIT, SET_ACC */
	int term_cond;
	double tolerance;
	double max_feed_scale;
	double axis_vmax[TP_N], axis_amax[TP_N];	/* TP_BIG = not set */
	int arc_blend, arc_fallback, opt_depth, gap_cycles;
	double ramp_freq, kink_ratio;
	double goal[TP_N];		/* end of the last queued segment */
	double pos[TP_N];		/* current commanded position */
	int last_motion_type;		/* of the last queued segment, for junction rules */
	int last_sync;
	/* pending for the next segment */
	rtapi_u64 dout_mask, dout_value, dout_end_mask, dout_end_value;
	int aout_count;
	struct tp_aout aout[TP_SEG_AIO_MAX];
	int sync_mode, spindle_num;
	double uu_per_rev;
	/* execution */
	int pausing, aborting, stepping, step_armed;
	double cur_vel;			/* path speed of the last cycle */
	int exec_id, exec_tag, exec_type;
	unsigned char exec_enables;
	/* spindle position synchronisation (carried over a chain of synced segments) */
	int sync_state;			/* 0 none, 1 wait index, 2 accelerating, 3 locked */
	int index_requested, index_seen;
	double sync_offset;		/* spindle revs at chain progress 0 */
	double sync_base;		/* progress of the chain before the current segment */
	double spindle_scale_out;	/* rigid tap spindle speed multiplier */
	struct tc q[];			/* size records */
};

/* geometry (tp_geom_fp.c) */
void tc_pos_at(const struct tc *tc, double s, double out[TP_N]);
void tc_tangent(const struct tc *tc, int at_end, double u[TP_N]);
double tp_norm(const double *v, int n);
double tp_dot(const double *a, const double *b, int n);
void pose_to_vec(const struct tp_pose *p, double v[TP_N]);
void vec_to_pose(const double v[TP_N], struct tp_pose *p);
int tc_line_init(struct tc *tc, const double start[TP_N], const double end[TP_N]);
int tc_circle_init(struct tc *tc, const double start[TP_N], const double end[TP_N],
		   const struct tp_cart *center, const struct tp_cart *normal, int turn);

/* queue helpers (tp_fp.c) */
struct tc *tp_seg(struct tp *tp, int i);	/* i-th queued, 0 = head */
const struct tc *tp_seg_c(const struct tp *tp, int i);

/* look-ahead (tp_add_fp.c) */
double tc_vmax_target(const struct tp *tp, const struct tc *tc);

#endif
