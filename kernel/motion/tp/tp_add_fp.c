/* tp_add_fp.c - queueing segments: per-segment limits (§10.1), the junction rules of
 * G61.1/G61/G64 (§10.2), tangency/kink check and 9D circular blend arcs (§10.4),
 * parabolic-blend fallback set-up (§10.3), and the look-ahead pass (§10.5).
 * Runs in motion-command-handler context; FP unit. */
#include "tp_internal.h"
#include "rtapi_math.h"
#include "rtapi_string.h"

#define REVERSAL_COS 0.99939082701909573	/* cos(2 deg): anti-parallel within 2 deg = reversal */
#define BLEND_ACC_NORMAL 0.86602540378443865	/* sqrt(1 - 0.5^2): normal share of a_max */

static double dmin(double a, double b)
{
	return a < b ? a : b;
}

/* Highest velocity the segment may ever be planned at: requested x max feed scale,
 * kinematic bound, global limit (not for pure rotary or position-synced moves). */
double tc_vmax_target(const struct tp *tp, const struct tc *tc)
{
	double v = tc->maxvel;
	if (tc->sync == TP_SYNC_NONE)
		v = dmin(v, tc->reqvel * tp->max_feed_scale);
	if (!tc->pure_rotary && tc->sync != TP_SYNC_POSITION)
		v = dmin(v, tp->vlimit);
	return v;
}

static int bad_move(const struct tp_move *mv)
{
	return !mv || !rtapi_isfinite(mv->vel) || !rtapi_isfinite(mv->ini_maxvel)
		|| !rtapi_isfinite(mv->acc) || mv->vel <= 0 || mv->ini_maxvel <= 0 || mv->acc <= 0;
}

static int bad_pose(const struct tp_pose *p)
{
	double v[TP_N];
	if (!p)
		return 1;
	pose_to_vec(p, v);
	for (int i = 0; i < TP_N; i++)
		if (!rtapi_isfinite(v[i]))
			return 1;
	return 0;
}

/* The per-axis bounds (if motmod set them) along a unit-path direction. */
static void axis_bounds(const struct tp *tp, const double dir[TP_N], double *v, double *a)
{
	for (int i = 0; i < TP_N; i++) {
		double d = rtapi_fabs(dir[i]);
		if (d < 1e-9)
			continue;
		*v = dmin(*v, tp->axis_vmax[i] / d);
		*a = dmin(*a, tp->axis_amax[i] / d);
	}
}

/* Fill the fields every segment kind shares from the command and pending state. */
static void tc_fill(struct tp *tp, struct tc *tc, const struct tp_move *mv)
{
	tc->reqvel = mv->vel;
	tc->maxvel = mv->ini_maxvel;
	tc->acc = dmin(mv->acc, tp->amax);
	tc->progress = 0;
	tc->nominal_len = tc->len;
	tc->vf = 0;
	tc->kink_vel = TP_BIG;
	tc->term = tp->term_cond;
	tc->blend_next = 0;
	tc->blend_tol = tp->tolerance;
	tc->blend_cos = 0;
	tc->motion_type = mv->motion_type;
	tc->id = mv->id;
	tc->tag = mv->tag;
	tc->atspeed = mv->atspeed;
	tc->probe_type = mv->probe_type;
	tc->enables = mv->enables;
	tc->sync = tp->sync_mode;
	tc->spindle_num = tp->spindle_num;
	tc->uu_per_rev = tp->uu_per_rev;
	tc->dout_mask = tp->dout_mask;
	tc->dout_value = tp->dout_value;
	tc->dout_end_mask = tp->dout_end_mask;
	tc->dout_end_value = tp->dout_end_value;
	tc->aout_count = tp->aout_count;
	for (int i = 0; i < tp->aout_count; i++)
		tc->aout[i] = tp->aout[i];
	tc->active = 0;
	tc->vel = 0;
	tc->blend_start_vel = 0;
	tc->blending_in = 0;
	tc->tap_phase = TAP_TAPPING;
	tc->tap_x = 0;
	tc->tap_scale = 1;
	tc->tap_revs_prev = 0;
	if (mv->motion_type == TP_MOTION_PROBING || tc->kind == TC_TAP)
		tc->term = TP_TERM_STOP;
}

static void pending_outputs_taken(struct tp *tp)
{
	tp->dout_mask = 0;
	tp->dout_value = 0;
	tp->dout_end_mask = 0;
	tp->dout_end_value = 0;
	tp->aout_count = 0;
}

/* Per-axis acceleration bound used by the kink check: the axis limit if motmod
 * gave one, else the segment's own acceleration. */
static double kink_abound(const struct tp *tp, int i, double seg_acc)
{
	return tp->axis_amax[i] < TP_BIG ? tp->axis_amax[i] : seg_acc;
}

/* Try a circular blend arc at the corner between the line prev (tail of the queue)
 * and the line next (not queued yet).  On success the arc is written to *arc, prev
 * and next are trimmed, and 1 is returned. */
static int make_blend_arc(struct tp *tp, struct tc *prev, struct tc *next, struct tc *arc,
			  const double u1[TP_N], const double u2[TP_N])
{
	if (prev->kind != TC_LINE || next->kind != TC_LINE || prev->linear_group < 0
	    || prev->linear_group != next->linear_group)
		return 0;
	double c2t = -tp_dot(u1, u2, TP_N);	/* cos(2 theta) */
	if (c2t > 1)
		c2t = 1;
	if (c2t < -1)
		c2t = -1;
	double theta = 0.5 * rtapi_acos(c2t);
	double st = rtapi_sin(theta), ct = rtapi_cos(theta), tt = st / ct;
	if (theta < 1e-6 || ct < 1e-9)
		return 0;
	/* tolerance: min of the non-zero G64 P values and a quarter of each length */
	double tol = dmin(0.25 * prev->nominal_len, 0.25 * next->nominal_len);
	if (prev->blend_tol > 0)
		tol = dmin(tol, prev->blend_tol);
	if (next->blend_tol > 0)
		tol = dmin(tol, next->blend_tol);
	double h_tol = tol / (1 - st), d_tol = ct * h_tol;
	double remain = prev->len - prev->progress;
	double l1 = dmin(remain, 0.5 * prev->nominal_len), l2 = 0.5 * next->len;
	double d_geom = dmin(dmin(l1, l2), d_tol);
	double r_geom = tt * d_geom;
	if (!(r_geom > TP_EPS))
		return 0;
	/* plane of the arc: b1 from centre to start point, b2 = u1 */
	double bis[TP_N], nb;
	for (int i = 0; i < TP_N; i++)
		bis[i] = u2[i] - u1[i];
	nb = tp_norm(bis, TP_N);
	if (!(nb > TP_EPS))
		return 0;
	for (int i = 0; i < TP_N; i++)
		bis[i] /= nb;
	/* bounds in the plane (a direction in it has per-axis share <= hypot(u1_i, bis_i)) */
	double a_max = dmin(prev->acc, next->acc), v_max = TP_BIG;
	for (int i = 0; i < TP_N; i++) {
		double w = rtapi_hypot(u1[i], bis[i]);
		if (w < 1e-9)
			continue;
		if (w > 1)
			w = 1;
		a_max = dmin(a_max, tp->axis_amax[i] / w);
		v_max = dmin(v_max, tp->axis_vmax[i] / w);
	}
	double a_n = BLEND_ACC_NORMAL * a_max;
	double v_goal = dmin(dmin(tc_vmax_target(tp, prev), tc_vmax_target(tp, next)), v_max);
	double v_plan = dmin(rtapi_sqrt(a_n * r_geom), v_goal);
	double r_plan = dmin(v_plan * v_plan / a_n, r_geom);
	double d_plan = r_plan / tt;
	if (!(d_plan > TP_EPS) || d_plan > l1 || d_plan > l2)
		return 0;
	/* a segment already moving must still be able to slow to v_plan before the arc */
	if (prev->active) {
		double left = prev->len - d_plan - prev->progress;
		if (left < 0 || (prev->vel * prev->vel - v_plan * v_plan) > 2 * prev->acc * left)
			return 0;
	}
	double corner[TP_N], t1[TP_N], t2[TP_N];
	for (int i = 0; i < TP_N; i++) {
		corner[i] = prev->end[i];
		t1[i] = corner[i] - u1[i] * d_plan;
		t2[i] = corner[i] + u2[i] * d_plan;
	}
	memset(arc, 0, sizeof(*arc));
	arc->kind = TC_BLEND;
	arc->br = r_plan;
	for (int i = 0; i < TP_N; i++) {
		arc->bc[i] = corner[i] + bis[i] * (r_plan / st);
		arc->b1[i] = (t1[i] - arc->bc[i]) / r_plan;
		arc->b2[i] = u1[i];
		arc->start[i] = t1[i];
		arc->end[i] = t2[i];
	}
	arc->len = r_plan * (TP_PI - 2 * theta);
	arc->nominal_len = arc->len;
	arc->linear_group = prev->linear_group;
	arc->pure_rotary = prev->pure_rotary;
	arc->reqvel = dmin(prev->reqvel, next->reqvel);
	arc->maxvel = v_plan;
	arc->acc = 0.5 * a_max;			/* tangential share */
	arc->vf = 0;
	arc->kink_vel = TP_BIG;
	arc->term = TP_TERM_TANGENT;
	arc->motion_type = next->motion_type;
	arc->id = prev->id;
	arc->tag = prev->tag;
	arc->enables = prev->enables;
	arc->sync = prev->sync;
	arc->spindle_num = prev->spindle_num;
	arc->uu_per_rev = prev->uu_per_rev;
	arc->tap_scale = 1;
	/* trim the neighbours to the tangent points */
	prev->len -= d_plan;
	for (int i = 0; i < TP_N; i++)
		prev->end[i] = t1[i];
	prev->term = TP_TERM_TANGENT;
	prev->kink_vel = v_plan;
	next->len -= d_plan;
	for (int i = 0; i < TP_N; i++)
		next->start[i] = t2[i];
	return 1;
}

/* Decide how prev (the queue tail) ends now that next follows it.  May fill *arc
 * (returns 1 then: queue the arc before next). */
static int resolve_junction(struct tp *tp, struct tc *prev, struct tc *next, struct tc *arc)
{
	int req = prev->term;
	prev->term = TP_TERM_STOP;
	prev->blend_next = 0;
	if (req == TP_TERM_STOP || prev->kind == TC_TAP || next->kind == TC_TAP
	    || prev->motion_type == TP_MOTION_PROBING || next->motion_type == TP_MOTION_PROBING)
		return 0;
	if ((prev->motion_type == TP_MOTION_TRAVERSE) != (next->motion_type == TP_MOTION_TRAVERSE))
		return 0;	/* can't blend between rapid and feed motions */
	if (prev->sync != next->sync)
		return 0;	/* includes the start of a position-synchronized chain */
	double u1[TP_N], u2[TP_N];
	tc_tangent(prev, 1, u1);
	tc_tangent(next, 0, u2);
	double cosang = tp_dot(u1, u2, TP_N);
	if (cosang < -REVERSAL_COS)
		return 0;	/* sharp reversal */
	double vmx = dmin(tc_vmax_target(tp, prev), tc_vmax_target(tp, next));
	double a_inst = vmx / tp->cycle + prev->acc, r = 0;
	for (int i = 0; i < TP_N; i++) {
		double ri = rtapi_fabs(a_inst * (u2[i] - u1[i]))
			/ kink_abound(tp, i, dmin(prev->acc, next->acc));
		if (ri > r)
			r = ri;
	}
	if (prev->kind == TC_CIRCLE || next->kind == TC_CIRCLE)
		r /= 0.5;
	if (r < tp->kink_ratio) {
		/* tangent: keep speed, leave acceleration room for the small kink */
		prev->term = TP_TERM_TANGENT;
		prev->kink_vel = vmx;
		prev->acc *= 1 - r;
		next->acc *= 1 - r;
		return 0;
	}
	prev->kink_vel = vmx * tp->kink_ratio / r;
	if (req != TP_TERM_PARABOLIC)
		return 0;	/* G61: stop at a real corner */
	if (tp->arc_blend && make_blend_arc(tp, prev, next, arc, u1, u2))
		return 1;
	if (tp->arc_blend && !tp->arc_fallback)
		return 0;
	/* parabolic overlap: both segments give up half their acceleration; a segment
	 * already moving must be able to stop with the halved value */
	if (prev->active) {
		double left = prev->len - prev->progress;
		if (prev->vel * prev->vel > prev->acc * left)
			return 0;
	}
	prev->term = TP_TERM_PARABOLIC;
	prev->blend_next = 1;
	prev->acc *= 0.5;
	next->acc *= 0.5;
	next->blending_in = 1;
	prev->blend_tol = prev->blend_tol > 0 ? prev->blend_tol : 0;
	prev->blend_cos = rtapi_cos(0.5 * rtapi_acos(-cosang > 1 ? 1 : (-cosang < -1 ? -1 : -cosang)));
	return 0;
}

/* Backward pass over tangent junctions (§10.5): exit velocities for look-ahead. */
static void optimize(struct tp *tp)
{
	int n = tp->count;
	if (n == 0)
		return;
	tp_seg(tp, n - 1)->vf = 0;
	for (int k = n - 2, depth = 0; k >= 0 && depth < tp->opt_depth; k--, depth++) {
		struct tc *t = tp_seg(tp, k), *nx = tp_seg(tp, k + 1);
		if (t->term != TP_TERM_TANGENT)
			break;
		double rest = nx->len - nx->progress;
		if (rest < 0)
			rest = 0;
		double v = rtapi_sqrt(nx->vf * nx->vf + 2 * nx->acc * rest);
		v = dmin(v, tc_vmax_target(tp, nx));
		v = dmin(v, tc_vmax_target(tp, t));
		v = dmin(v, t->kink_vel);
		if (v == t->vf && depth > 0)
			break;	/* nothing earlier can change */
		t->vf = v;
	}
}

/* Common tail of every add: junction with the queue tail, optional blend arc,
 * queue the segment, look-ahead. */
static int enqueue(struct tp *tp, struct tc *tc, const double goal[TP_N])
{
	/* tc was built in ring slot count + 1; slot count takes a blend arc if one is
	 * made, else tc moves down into it (no segment record on the stack: they are big) */
	struct tc *slot = tp_seg(tp, tp->count);
	int have_arc = 0;
	if (tp->count > 0)
		have_arc = resolve_junction(tp, tp_seg(tp, tp->count - 1), tc, slot);
	if (have_arc) {
		tp->count += 2;
	} else {
		*slot = *tc;
		tp->count++;
	}
	for (int i = 0; i < TP_N; i++)
		tp->goal[i] = goal[i];
	pending_outputs_taken(tp);
	optimize(tp);
	return 0;
}

/* Ring slot where a new segment is built (see enqueue). */
static struct tc *new_slot(struct tp *tp)
{
	struct tc *tc = tp_seg(tp, tp->count + 1);
	memset(tc, 0, sizeof(*tc));
	return tc;
}

static int add_prologue(struct tp *tp, const struct tp_pose *end, const struct tp_move *mv)
{
	if (tp->aborting)
		return TP_ERR_ABORTING;
	if (bad_pose(end) || bad_move(mv))
		return TP_ERR_INVALID;
	if (tp->size - tp->count < TP_ADD_MARGIN)
		return TP_ERR_QUEUE_FULL;
	return 0;
}

int tp_add_line(struct tp *tp, const struct tp_pose *end, const struct tp_move *mv)
{
	int err = add_prologue(tp, end, mv);
	if (err)
		return err;
	if (mv->motion_type != TP_MOTION_TRAVERSE && mv->motion_type != TP_MOTION_FEED
	    && mv->motion_type != TP_MOTION_PROBING && mv->motion_type != TP_MOTION_TOOLCHANGE
	    && mv->motion_type != TP_MOTION_INDEXROTARY)
		return TP_ERR_INVALID;
	struct tc *tc = new_slot(tp);
	double e[TP_N];
	pose_to_vec(end, e);
	if (tc_line_init(tc, tp->goal, e) == TP_ERR_ZERO_LENGTH)
		return 0;	/* nothing to move: accepted, dropped (pending outputs stay) */
	tc_fill(tp, tc, mv);
	double v = tc->maxvel, a = tc->acc;
	axis_bounds(tp, tc->dir, &v, &a);
	tc->maxvel = v;
	tc->acc = a;
	return enqueue(tp, tc, e);
}

int tp_add_circle(struct tp *tp, const struct tp_pose *end, const struct tp_cart *center,
		  const struct tp_cart *normal, int turn, const struct tp_move *mv)
{
	int err = add_prologue(tp, end, mv);
	if (err)
		return err;
	if (!center || !normal || !rtapi_isfinite(center->x) || !rtapi_isfinite(center->y)
	    || !rtapi_isfinite(center->z) || !rtapi_isfinite(normal->x)
	    || !rtapi_isfinite(normal->y) || !rtapi_isfinite(normal->z))
		return TP_ERR_INVALID;
	struct tc *tc = new_slot(tp);
	double e[TP_N];
	pose_to_vec(end, e);
	err = tc_circle_init(tc, tp->goal, e, center, normal, turn);
	if (err)
		return err;
	tc_fill(tp, tc, mv);
	/* curvature limit (§10.4 pmCircleActualMaxVel) */
	double rmin = tc->r0 < tc->r0 + tc->dr ? tc->r0 : tc->r0 + tc->dr;
	double drda = tc->dr / tc->angle;
	double r_eff = rtapi_sqrt(drda * drda + rmin * rmin);
	double a = tc->acc, a_cut = BLEND_ACC_NORMAL * a;
	double v_req = dmin(tc->reqvel * tp->max_feed_scale, tc->maxvel);
	if (v_req * v_req / r_eff > a_cut) {
		tc->maxvel = rtapi_sqrt(a_cut * r_eff);
		tc->acc = 0.5 * a;
	} else {
		double q = v_req * v_req / (r_eff * a);
		tc->acc = rtapi_sqrt(1 - q * q) * a;
	}
	return enqueue(tp, tc, e);
}

int tp_add_rigid_tap(struct tp *tp, const struct tp_pose *end, double reversal_scale,
		     const struct tp_move *mv)
{
	int err = add_prologue(tp, end, mv);
	if (err)
		return err;
	if (!rtapi_isfinite(reversal_scale) || reversal_scale <= 0)
		return TP_ERR_INVALID;
	if (tp->uu_per_rev == 0)
		return TP_ERR_NO_SYNC;
	struct tc *tc = new_slot(tp);
	double e[TP_N], back[TP_N];
	pose_to_vec(end, e);
	if (tc_line_init(tc, tp->goal, e) == TP_ERR_ZERO_LENGTH)
		return TP_ERR_INVALID;
	tc->kind = TC_TAP;
	tc_fill(tp, tc, mv);
	tc->sync = TP_SYNC_POSITION;
	tc->tap_scale = reversal_scale;
	double v = tc->maxvel, a = tc->acc;
	axis_bounds(tp, tc->dir, &v, &a);
	tc->maxvel = v;
	tc->acc = a;
	for (int i = 0; i < TP_N; i++)
		back[i] = tp->goal[i];	/* a tap ends where it started */
	return enqueue(tp, tc, back);
}
