/* tp_run_fp.c - one planner cycle (motion-controller, COORD mode): per-cycle trapezoid
 * with final velocity and time carried over tangent junctions (§10.5), parabolic
 * overlap (§10.3), spindle synchronisation and rigid tap (§10.7), probe trip (§13),
 * pause/abort/step, synchronized outputs at segment start.  FP unit. */
#include "tp_internal.h"
#include "rtapi_math.h"
#include "rtapi_string.h"

static double dmin(double a, double b)
{
	return a < b ? a : b;
}

static double dmax(double a, double b)
{
	return a > b ? a : b;
}

/* Drop the head segment. */
static void pop(struct tp *tp)
{
	tp->head = (tp->head + 1) % tp->size;
	tp->count--;
}

/* Target speed of tc this cycle (§10.1): requested (or spindle-derived) x scale,
 * capped by the planning bound; 0 while pausing/aborting unless position-synced. */
static double target_vel(const struct tp *tp, const struct tc *tc, const struct tp_inputs *in)
{
	double vmax = tc_vmax_target(tp, tc);
	if (tc->sync == TP_SYNC_POSITION)
		return vmax;	/* the sync law below decides */
	double scale = tc->motion_type == TP_MOTION_TRAVERSE ? in->rapid_scale : in->feed_scale;
	if (!(scale > 0) || tp->pausing || tp->aborting)
		return 0;
	double req = tc->reqvel;
	if (tc->sync == TP_SYNC_VELOCITY)
		req = rtapi_fabs(in->spindle_speed) * tc->uu_per_rev;
	if (tc->overlap || tc->blend_next)
		scale = dmin(scale, 1.0);
	return dmin(req * scale, vmax);
}

/* Adds a segment's synchronized outputs to this period's: its start values, or
 * (at_end) the ones that change at its end. Later calls override earlier ones. */
static void emit_outputs(const struct tc *tc, struct tp_outputs *out, int at_end)
{
	rtapi_u64 mask = at_end ? tc->dout_end_mask : tc->dout_mask;
	rtapi_u64 value = at_end ? tc->dout_end_value : tc->dout_value;

	out->dout_mask |= mask;
	out->dout_value = (out->dout_value & ~mask) | (value & mask);
	for (int i = 0; i < tc->aout_count; i++) {
		int j;
		if (at_end && !tc->aout[i].has_end)
			continue;
		for (j = 0; j < out->aout_count; j++)
			if (out->aout[j].index == tc->aout[i].index)
				break;
		if (j == out->aout_count) {
			if (j >= TP_SEG_AIO_MAX)
				continue;
			out->aout_count++;
		}
		out->aout[j] = tc->aout[i];
		if (at_end)
			out->aout[j].value = tc->aout[i].end;
	}
}

/* Synchronized outputs and identity of a segment that starts moving now. */
static void activate(struct tp *tp, struct tc *tc, struct tp_outputs *out)
{
	tc->active = 1;
	emit_outputs(tc, out, 0);
	if (tp->stepping && !tp->step_armed)
		tp->step_armed = 1;
}

/* One trapezoid update of tc over time dt toward exit velocity vf.  Returns the time
 * used: dt, or less when the segment end was reached inside the cycle. */
static double trap_step(struct tc *tc, double vt, double vf, double dt)
{
	double a = tc->acc, v = tc->vel, dx = tc->len - tc->progress;
	if (dx <= 0) {
		tc->progress = tc->len;
		return 0;
	}
	/* does the end come inside this cycle?  Then arrive at the exit velocity (as far
	 * as the acceleration allows) and hand the rest of the cycle on (§10.5 split) */
	double ae = (vf * vf - v * v) / (2 * dx);
	double ad = (vt - v) / dt;
	if (ae > ad)
		ae = ad;
	if (ae > a)
		ae = a;
	if (ae < -a)
		ae = -a;
	double ve2 = v * v + 2 * ae * dx;
	if (ve2 >= 0) {
		double ve = rtapi_sqrt(ve2), t;
		if (rtapi_fabs(ae) > 1e-9)
			t = (ve - v) / ae;
		else
			t = v > 0 ? dx / v : 2 * dt;
		if (t <= dt && t >= 0) {
			tc->vel = ve;
			tc->progress = tc->len;
			tc->decel = 1;
			return t;
		}
	}
	double disc = vf * vf + a * (2 * dx - v * dt) + 0.25 * a * a * dt * dt;
	double vreach = disc > 0 ? -0.5 * a * dt + rtapi_sqrt(disc) : 0;
	double vnew = dmax(dmin(vreach, vt), 0);
	tc->decel = vreach < vt;
	double acc = (vnew - v) / dt;
	if (acc > a)
		acc = a;
	if (acc < -a)
		acc = -a;
	double vnext = v + acc * dt;
	if (vnext < 0)
		vnext = 0;
	double step = 0.5 * (v + vnext) * dt;
	if (step >= dx) {	/* numerically at the end */
		tc->vel = vnext;
		tc->progress = tc->len;
		return dt;
	}
	tc->progress += step;
	tc->vel = vnext;
	return dt;
}

/* Position-following law of synchronized moves: velocity toward the spindle
 * position with bounded acceleration (§10.7).  Returns the new signed velocity. */
static double follow(double v, double spos, double x, double spd, double a, double vmax, double dt)
{
	/* error against where we are after this cycle at the spindle's speed */
	double e = spos - x - 0.5 * (v + spd) * dt;
	double corr = rtapi_sqrt(rtapi_fabs(e) * a);
	if (corr > rtapi_fabs(e) / dt)
		corr = rtapi_fabs(e) / dt;
	double vt = spd + (e >= 0 ? corr : -corr);
	if (vt > vmax)
		vt = vmax;
	if (vt < -vmax)
		vt = -vmax;
	if (vt > v + a * dt)
		vt = v + a * dt;
	if (vt < v - a * dt)
		vt = v - a * dt;
	return vt;
}

/* Rigid tap (G33.1): in synchronized, spindle reversed at depth, out synchronized,
 * spindle forward again, then an unsynchronized placement on the start point.
 * Returns 1 when the tap is complete. */
static int tap_step(struct tp *tp, struct tc *tc, const struct tp_inputs *in, double dt)
{
	double k = tc->uu_per_rev, a = tc->acc, vmax = tc->maxvel, revs = in->spindle_revs;
	double v = tc->vel, x = tc->tap_x, vn;
	if (tc->tap_phase == TAP_FINAL_PLACEMENT) {
		/* unsynchronized trapezoid from tap_x0 back to the start point (x = 0) */
		trap_step(tc, tc->maxvel, 0, dt);
		double sgn = tc->tap_x0 > 0 ? -1 : 1;
		tc->tap_x = tc->tap_x0 + sgn * tc->progress;
		if (tc->progress >= tc->len) {
			tc->tap_x = 0;
			tc->vel = 0;
			return 1;
		}
		return 0;
	}
	double spos = (revs - tp->sync_offset) * k;
	vn = follow(v, spos, x, in->spindle_speed * k, a, vmax, dt);
	x += 0.5 * (v + vn) * dt;
	switch (tc->tap_phase) {
	case TAP_TAPPING:
		if (x >= tc->len) {
			tc->tap_phase = TAP_REVERSING;
			tp->spindle_scale_out = -tc->tap_scale;
		}
		break;
	case TAP_REVERSING:
		if (revs < tc->tap_revs_prev)
			tc->tap_phase = TAP_RETRACTION;
		break;
	case TAP_RETRACTION:
		if (x <= 0) {
			tc->tap_phase = TAP_FINAL_REVERSAL;
			tp->spindle_scale_out = 1.0;
		}
		break;
	case TAP_FINAL_REVERSAL:
		if (revs > tc->tap_revs_prev) {
			tc->tap_phase = TAP_FINAL_PLACEMENT;
			tc->tap_x0 = x;
			tc->len = rtapi_fabs(x);
			tc->progress = 0;
			/* keep the speed if it already points at the start point */
			vn = (x < 0) == (vn > 0) ? rtapi_fabs(vn) : 0;
		}
		break;
	default:
		break;
	}
	tc->tap_revs_prev = revs;
	tc->tap_x = x;
	tc->vel = vn;
	if (tc->tap_phase == TAP_FINAL_PLACEMENT && tc->len <= TP_EPS) {
		tc->tap_x = 0;
		return 1;
	}
	return 0;
}

/* Gate a segment that is about to start from rest: at-speed, spindle index.
 * Returns 1 when it may start this cycle. */
static int may_start(struct tp *tp, struct tc *tc, const struct tp_inputs *in,
		     struct tp_outputs *out)
{
	if (tp->pausing && tc->sync != TP_SYNC_POSITION)
		return 0;
	if (tc->atspeed && !in->spindle_at_speed) {
		out->waiting_for_atspeed = 1;
		return 0;
	}
	if (tc->kind == TC_TAP) {
		tp->sync_offset = in->spindle_revs;	/* follows the spindle from here */
		tp->sync_state = 3;
		tc->tap_revs_prev = in->spindle_revs;
		return 1;
	}
	if (tc->sync != TP_SYNC_POSITION)
		return 1;
	if (tp->sync_state >= 2) {
		/* a stop inside a synchronized chain: catch the spindle up again and re-lock
		 * the phase instead of chasing the revolutions turned while standing */
		tp->sync_state = 2;
		tp->sync_base = 0;
		return 1;
	}
	if (tp->sync_state == 0) {
		tp->sync_state = 1;
		tp->index_seen = 0;
		out->spindle_index_request = 1;
		out->waiting_for_index = 1;
		return 0;
	}
	if (in->spindle_index_enable) {
		tp->index_seen = 1;
		out->waiting_for_index = 1;
		return 0;
	}
	if (!tp->index_seen) {
		out->waiting_for_index = 1;
		return 0;
	}
	tp->sync_state = 2;			/* index found: accelerate to spindle speed */
	tp->sync_offset = in->spindle_revs;
	tp->sync_base = 0;
	return 1;
}

/* Exit velocity of the head for this cycle. */
static double exit_vel(const struct tp *tp, const struct tc *tc, const struct tp_inputs *in)
{
	if (tc->term != TP_TERM_TANGENT || tp->count < 2 || (tp->stepping && tp->step_armed))
		return 0;
	const struct tc *nx = tp_seg_c(tp, 1);
	if (nx->sync == TP_SYNC_POSITION)
		return tc->vf;
	return dmin(tc->vf, dmax(target_vel(tp, nx, in), 0));
}

/* Blend velocity of a parabolic junction (§10.3, 2.9 fallback form). */
static double blend_vel(const struct tp *tp, const struct tc *a, const struct tc *b,
			const struct tp_inputs *in)
{
	double acc = dmin(a->acc, b->acc);
	double vb = dmin(target_vel(tp, b, in), rtapi_sqrt(b->acc * b->len));
	vb = dmin(vb, target_vel(tp, a, in));
	if (a->blend_tol > 0 && a->blend_cos > 1e-3)
		vb = dmin(vb, 2 * rtapi_sqrt(acc * a->blend_tol / a->blend_cos));
	return vb;
}

/* Advance synchronized (position) segment tc over dt. */
static double sync_step(struct tp *tp, struct tc *tc, const struct tp_inputs *in, double vf,
			double dt)
{
	double k = tc->uu_per_rev, vt;
	if (tp->sync_state == 2) {
		vt = tc_vmax_target(tp, tc);
	} else {
		double p = tp->sync_base + tc->progress;
		double spos = (in->spindle_revs - tp->sync_offset) * k;
		vt = follow(tc->vel, spos, p, in->spindle_speed * k, tc->acc, tc_vmax_target(tp, tc), dt);
		if (vt < 0)
			vt = 0;
	}
	double used = trap_step(tc, vt, vf, dt);
	if (tp->sync_state == 2 && tc->vel >= rtapi_fabs(in->spindle_speed * k)) {
		/* matched the spindle: fix the offset so the position error is zero */
		tp->sync_state = 3;
		tp->sync_offset = in->spindle_revs - (tp->sync_base + tc->progress) / k;
	}
	return used;
}

static void fill_status(struct tp *tp, struct tp_outputs *out, double dist, double dt)
{
	vec_to_pose(tp->pos, &out->pos);
	tp->cur_vel = dist / dt;
	if (tp->cur_vel < 1e-12)
		tp->cur_vel = 0;
	out->current_vel = tp->cur_vel;
	out->queue_depth = tp->count;
	out->active_depth = tp_active_depth(tp);
	out->queue_full = tp_is_queue_full(tp);
	out->done = tp->count == 0;
	out->paused = tp->pausing && tp->cur_vel == 0;
	out->spindle_speed_scale = tp->spindle_scale_out;
	out->exec_id = tp->exec_id;
	out->exec_tag = tp->exec_tag;
	out->motion_type = tp->exec_type;
	out->enables_queued = tp->exec_enables;
	if (tp->count == 0) {
		tp->exec_id = tp->exec_tag = tp->exec_type = 0;
		tp->exec_enables = 0;
		out->exec_id = out->exec_tag = out->motion_type = 0;
		out->enables_queued = 0;
	}
	if (tp->count > 0) {
		const struct tc *h = tp_seg_c(tp, 0);
		double d[TP_N];
		for (int i = 0; i < TP_N; i++)
			d[i] = h->end[i] - tp->pos[i];
		vec_to_pose(d, &out->dtg);
		out->distance_to_go = h->kind == TC_TAP ? rtapi_fabs(h->len - h->tap_x)
							: h->len - h->progress;
		out->requested_vel = h->reqvel;
		out->spindle_sync = h->sync != TP_SYNC_NONE;	/* waiting (index, at-speed) or moving */
		out->spindle_num = h->spindle_num;
		out->probing = h->motion_type == TP_MOTION_PROBING;
	}
}

static void set_exec(struct tp *tp, const struct tc *tc)
{
	tp->exec_id = tc->id;
	tp->exec_tag = tc->tag;
	tp->exec_type = tc->motion_type;
	tp->exec_enables = tc->enables;
}

int tp_run_cycle(struct tp *tp, const struct tp_inputs *in, struct tp_outputs *out)
{
	if (!tp || !in || !out)
		return TP_ERR_INVALID;
	double dt = tp->cycle, prev_pos[TP_N];
	memset(out, 0, sizeof(*out));
	for (int i = 0; i < TP_N; i++)
		prev_pos[i] = tp->pos[i];
	if (tp->count == 0) {
		if (tp->aborting)
			tp_clear(tp);
		tp->exec_id = tp->exec_tag = tp->exec_type = 0;
		tp->sync_state = 0;
		fill_status(tp, out, 0, dt);
		return 0;
	}
	struct tc *h = tp_seg(tp, 0);
	/* probe: the level test while a probe segment runs (§13) */
	if (h->motion_type == TP_MOTION_PROBING && !tp->aborting) {
		int trip = (h->probe_type & TP_PROBE_LOSS) ? !in->probe_input : !!in->probe_input;
		if (trip) {
			out->probe_tripped = 1;
			vec_to_pose(tp->pos, &out->probed_pos);
			tp->aborting = 1;
		}
	}
	if (!h->active) {
		if (tp->aborting) {
			tp_clear(tp);
			fill_status(tp, out, 0, dt);
			return 0;
		}
		if (!may_start(tp, h, in, out)) {
			fill_status(tp, out, 0, dt);
			return 0;
		}
		activate(tp, h, out);
		set_exec(tp, h);
	}
	double t_left = dt;
	for (;;) {
		h = tp_seg(tp, 0);
		struct tc *b = tp->count > 1 ? tp_seg(tp, 1) : 0;
		int overlap = b && b->overlap;
		int finished;
		if (h->kind == TC_TAP) {
			finished = tap_step(tp, h, in, t_left);
			t_left = 0;
		} else {
			double vf = exit_vel(tp, h, in), used;
			if (h->sync == TP_SYNC_POSITION)
				used = sync_step(tp, h, in, vf, t_left);
			else
				used = trap_step(h, target_vel(tp, h, in), vf, t_left);
			finished = h->progress >= h->len;
			if (overlap) {
				/* second half of a parabolic blend: keep the sum of speeds */
				double vt = dmin(target_vel(tp, b, in), dmax(b->blend_start_vel - h->vel, 0));
				trap_step(b, vt, exit_vel(tp, b, in), dt);
			}
			t_left -= used;
		}
		if (!finished)
			break;
		/* the head reached its end */
		emit_outputs(h, out, 1);
		if (h->motion_type == TP_MOTION_PROBING && !out->probe_tripped) {
			out->probe_no_contact = 1;
			vec_to_pose(h->end, &out->probed_pos);
		}
		int tangent = h->term == TP_TERM_TANGENT && b && !(tp->stepping && tp->step_armed)
			&& h->vel > 0;
		if (h->sync == TP_SYNC_POSITION)
			tp->sync_base += h->len;
		double v_end = h->vel;
		for (int i = 0; i < TP_N; i++)	/* a tap ends where it started */
			tp->pos[i] = h->kind == TC_TAP ? h->start[i] : h->end[i];
		pop(tp);
		if (tp->count == 0 || !b || b->sync != TP_SYNC_POSITION)
			tp->sync_state = 0;
		if (tp->stepping && tp->step_armed) {
			tp->stepping = 0;
			tp->step_armed = 0;
			tp->pausing = 1;
		}
		if (overlap) {
			b->overlap = 0;
			set_exec(tp, b);
			break;
		}
		if (!tangent || t_left <= 0) {
			if (tangent && b) {	/* exactly at the junction: carry speed on */
				b->vel = v_end;
				activate(tp, b, out);
				set_exec(tp, b);
			}
			break;
		}
		b->vel = v_end;
		activate(tp, b, out);
		set_exec(tp, b);
	}
	/* parabolic blend start: the head is in its final deceleration below v_b */
	h = tp->count ? tp_seg(tp, 0) : 0;
	if (h && h->blend_next && tp->count > 1 && !tp->pausing && !tp->aborting
	    && !(tp->stepping && tp->step_armed)) {
		struct tc *b = tp_seg(tp, 1);
		if (!b->overlap && !b->active && h->decel && h->vel <= blend_vel(tp, h, b, in)) {
			b->overlap = 1;
			b->blend_start_vel = h->vel;
			b->vel = 0;
			activate(tp, b, out);
		}
	}
	/* commanded position: head, plus the displacement of an overlapping second segment */
	double dist = 0;
	if (h) {
		double p[TP_N];
		if (h->kind == TC_TAP)
			tc_pos_at(h, h->tap_x, p);
		else
			tc_pos_at(h, h->progress, p);
		if (tp->count > 1 && tp_seg(tp, 1)->overlap) {
			struct tc *b = tp_seg(tp, 1);
			double q[TP_N];
			tc_pos_at(b, b->progress, q);
			for (int i = 0; i < TP_N; i++)
				p[i] += q[i] - b->start[i];
			if (b->vel > h->vel)
				set_exec(tp, b);
		}
		for (int i = 0; i < TP_N; i++)
			tp->pos[i] = p[i];
	}
	{
		double d[TP_N];
		for (int i = 0; i < TP_N; i++)
			d[i] = tp->pos[i] - prev_pos[i];
		dist = tp_norm(d, 3) > TP_EPS ? tp_norm(d, 3)
			: (tp_norm(d + 6, 3) > TP_EPS ? tp_norm(d + 6, 3) : tp_norm(d + 3, 3));
	}
	/* abort completes once everything stands still */
	if (tp->aborting && dist == 0 && (!h || h->vel == 0)
	    && !(h && h->sync == TP_SYNC_POSITION && h->active && h->vel != 0)) {
		tp_clear(tp);
	}
	fill_status(tp, out, dist, dt);
	return 0;
}
