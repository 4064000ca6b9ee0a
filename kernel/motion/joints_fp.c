/* SPDX-License-Identifier: GPL-2.0-or-later */
/* joints_fp.c - the per-joint parts of motion-controller: feedback, following error
 * and limit switches (motion.md 11), joint faults, jog-stop, joint and axis jog wheels
 * and the free planners (12), backlash/screw compensation (8) and the joint pins. */
#include "motmod_priv.h"
#include "rtapi_math.h"

static void stop_jogs(struct motmod *m, bool immediate)
{
	int j, l;

	for (j = 0; j < m->num_joints; j++) {
		struct mot_joint *jt = &m->joint[j];

		if (!jt->kb_jog_active && !jt->wheel_jog_active)
			continue;
		jt->free.enable = false;
		if (immediate) {
			jt->free.curr_vel = 0.0;
			jt->free.pos_cmd = jt->free.curr_pos;
		}
		jt->kb_jog_active = jt->wheel_jog_active = false;
	}
	for (l = 0; l < MOTION_MAX_AXES; l++) {
		struct mot_axis *ax = &m->axis[l];

		if (!ax->kb_jog_active && !ax->wheel_jog_active)
			continue;
		ax->tp.enable = false;
		if (immediate) {
			ax->tp.curr_vel = 0.0;
			ax->tp.pos_cmd = ax->tp.curr_pos;
		}
		ax->kb_jog_active = ax->wheel_jog_active = false;
	}
}

void mot_process_joint_inputs(struct motmod *m)
{
	struct mot_pins *p = m->pins;
	bool jogging = false;
	int j, l;

	for (j = 0; j < m->num_joints; j++) {
		struct mot_joint *jt = &m->joint[j];
		struct mot_joint_pins *jp = &p->joint[j];
		double abs_ferror, limit;

		if (!jt->active)
			continue;
		/* at the index the encoder jumps: hide it for that period (homing.h) */
		if (get_homing_at_index_search_wait(j) && !get_index_enable(j))
			jt->pos_fb = jt->pos_cmd;
		else
			jt->pos_fb = *jp->motor_pos_fb - (jt->backlash_filt + jt->motor_offset);
		jt->ferror = jt->pos_cmd - jt->pos_fb;
		abs_ferror = rtapi_fabs(jt->ferror);
		limit = jt->vel_limit > 0.0 ? jt->max_ferror * rtapi_fabs(jt->vel_cmd) / jt->vel_limit : 0.0;
		if (limit < jt->min_ferror)
			limit = jt->min_ferror;
		jt->ferror_limit = limit;
		jt->ferrored = abs_ferror > limit;
		if (abs_ferror > jt->ferror_high_mark)
			jt->ferror_high_mark = abs_ferror;
		jt->on_pos_limit = *jp->pos_lim_sw_in;
		jt->on_neg_limit = *jp->neg_lim_sw_in;
		if (jt->kb_jog_active || jt->wheel_jog_active)
			jogging = true;
	}
	for (l = 0; l < MOTION_MAX_AXES; l++)
		if (m->axis[l].kb_jog_active || m->axis[l].wheel_jog_active)
			jogging = true;
	if (jogging && (*p->jog_stop || *p->jog_stop_immediate)) {
		stop_jogs(m, *p->jog_stop_immediate);
		mot_error(m, "Jog aborted by jog-stop%s", *p->jog_stop_immediate ? "-immediate" : "");
	}
}

void mot_check_joint_faults(struct motmod *m)
{
	int j;

	for (j = 0; j < m->num_joints; j++) {
		struct mot_joint *jt = &m->joint[j];
		unsigned int neg_bit = 1u << (2 * j), pos_bit = 2u << (2 * j);
		bool pos = jt->on_pos_limit && !(m->override_mask & pos_bit);
		bool neg = jt->on_neg_limit && !(m->override_mask & neg_bit);

		if (!jt->active || !jt->enabled)
			continue;
		if ((pos || neg) && !get_homing(j)) {
			if (!jt->limit_reported) {
				mot_error(m, "joint %d on limit switch error", j);
				jt->limit_reported = true;
			}
			jt->error = true;
			m->disable_req = true;
		} else if (!jt->on_pos_limit && !jt->on_neg_limit) {
			jt->limit_reported = false;
		}
		if (*m->pins->joint[j].amp_fault_in) {
			mot_error(m, "joint %d amplifier fault", j);
			jt->fault = true;
			m->disable_req = true;
		}
		if (jt->ferrored) {
			mot_error(m, "joint %d following error", j);
			jt->error = true;
			m->disable_req = true;
		}
	}
}

/* One wheel: counts since the last period moved into a planner target (motion.md 12).
 * Returns true when the wheel moved the target. */
static bool wheel(struct freetp *tp, rtapi_s32 counts, rtapi_s32 *old, bool *init, double scale,
		  bool vel_mode, double accel_fraction, double max_vel, double max_acc,
		  double net_scale, double lo, double hi, bool on_pos, bool on_neg)
{
	rtapi_s32 delta = counts - *old;
	double target, stop_dist, v, a;

	*old = counts;
	if (!*init) {
		*init = true;
		return false;
	}
	if (!delta || net_scale < 0.0001)
		return false;
	target = tp->pos_cmd + delta * scale;
	if (target > hi || target < lo)
		return false;	/* discarded, not clipped */
	if ((target > tp->pos_cmd && on_pos) || (target < tp->pos_cmd && on_neg))
		return false;
	a = (accel_fraction >= 0.0 && accel_fraction <= 1.0 ? accel_fraction : 1.0) * max_acc;
	v = max_vel * (net_scale < 1.0 ? net_scale : 1.0);
	if (vel_mode && a > 0.0) {
		/* the target may not lead by more than the stopping distance */
		stop_dist = v * v / (2.0 * a);
		if (target > tp->curr_pos + stop_dist)
			target = tp->curr_pos + stop_dist;
		else if (target < tp->curr_pos - stop_dist)
			target = tp->curr_pos - stop_dist;
	}
	tp->pos_cmd = target;
	tp->max_vel = v;
	tp->max_acc = a;
	tp->enable = true;
	return true;
}

void mot_joint_jog_wheels(struct motmod *m, bool allowed)
{
	int j;

	for (j = 0; j < m->num_joints; j++) {
		struct mot_joint *jt = &m->joint[j];
		struct mot_joint_pins *jp = &m->pins->joint[j];
		double lo, hi;

		if (!allowed || !*jp->jog_enable || !jt->active || !m->enabled || get_homing_is_active() ||
		    jt->kb_jog_active || (get_home_is_synchronized(j) && !get_homed(j))) {
			jt->old_jog_counts = *jp->jog_counts;	/* counts while disabled are not kept */
			continue;
		}
		if (get_home_needs_unlock_first(j)) {
			if (*jp->jog_counts != jt->old_jog_counts)
				mot_error(m, "Can't wheel jog locking joint_num=%d", j);
			jt->old_jog_counts = *jp->jog_counts;
			continue;
		}
		mot_joint_jog_limits(m, j, &lo, &hi);
		if (wheel(&jt->free, *jp->jog_counts, &jt->old_jog_counts, &jt->jog_counts_init,
			  *jp->jog_scale, *jp->jog_vel_mode, *jp->jog_accel_fraction, jt->vel_limit,
			  jt->acc_limit, m->net_feed_scale, lo, hi, jt->on_pos_limit, jt->on_neg_limit))
			jt->wheel_jog_active = true;
	}
}

void mot_axis_jog_wheels(struct motmod *m, bool allowed)
{
	int l;

	for (l = 0; l < MOTION_MAX_AXES; l++) {
		struct mot_axis *ax = &m->axis[l];
		struct mot_axis_pins *ap = &m->pins->axis[l];

		if (!allowed || !*ap->jog_enable || !m->enabled || ax->kb_jog_active) {
			ax->old_jog_counts = *ap->jog_counts;
			continue;
		}
		if (wheel(&ax->tp, *ap->jog_counts, &ax->old_jog_counts, &ax->jog_counts_init,
			  *ap->jog_scale, *ap->jog_vel_mode, *ap->jog_accel_fraction, ax->vel_limit,
			  ax->acc_limit, m->net_feed_scale, ax->min_limit, ax->max_limit, false, false))
			ax->wheel_jog_active = true;
	}
}

/* FREE: every active joint's planner (homing owns its target while homing) */
void mot_free_planners(struct motmod *m)
{
	int j;

	for (j = 0; j < m->num_joints; j++) {
		struct mot_joint *jt = &m->joint[j];
		unsigned int bits = 3u << (2 * j);

		if (!jt->active)
			continue;
		if (!get_homing(j) && !jt->wheel_jog_active) {
			jt->free.max_acc = jt->acc_limit;
			if (jt->free.max_vel > jt->vel_limit || jt->free.max_vel <= 0.0)
				jt->free.max_vel = jt->vel_limit;
		}
		freetp_update(&jt->free, m->servo_period_s);
		jt->pos_cmd = jt->free.curr_pos;
		jt->vel_cmd = jt->free.curr_vel;
		if (!jt->free.active) {
			jt->kb_jog_active = jt->wheel_jog_active = false;
			/* the limit override ends with the jog that left the switch */
			if ((m->override_mask & bits) && !jt->on_pos_limit && !jt->on_neg_limit &&
			    jt->was_on_limit)
				m->override_mask &= ~bits;
		}
	}
}

void mot_compensation(struct motmod *m)
{
	int j;

	for (j = 0; j < m->num_joints; j++) {
		struct mot_joint *jt = &m->joint[j];
		double scale = m->net_feed_scale < 1.0 ? m->net_feed_scale : 1.0;

		if (!jt->active)
			continue;
		jt->backlash_corr = comp_correction(&jt->comp, jt->backlash, jt->pos_cmd, jt->vel_cmd,
						    jt->backlash_corr);
		/* half the joint's velocity and acceleration are reserved for comp */
		comp_filter(jt->backlash_corr, &jt->backlash_filt, &jt->backlash_vel,
			    0.5 * jt->vel_limit * scale, 0.5 * jt->acc_limit, m->servo_period_s);
	}
}

void mot_joint_outputs(struct motmod *m)
{
	int j, first_extra = m->num_joints - m->num_extrajoints;

	for (j = 0; j < m->num_joints; j++) {
		struct mot_joint *jt = &m->joint[j];
		struct mot_joint_pins *jp = &m->pins->joint[j];

		if (j >= first_extra && get_homed(j) && m->enabled)
			jt->pos_cmd = *jp->posthome_cmd;	/* extra joints follow posthome-cmd */
		*jp->motor_pos_cmd = jt->pos_cmd + jt->backlash_filt + jt->motor_offset;
		*jp->pos_cmd = jt->pos_cmd;
		*jp->pos_fb = jt->pos_fb;
		*jp->coarse_pos_cmd = jt->coarse_pos;
		*jp->vel_cmd = jt->vel_cmd;
		*jp->acc_cmd = jt->acc_cmd;
		*jp->motor_offset = jt->motor_offset;
		*jp->amp_enable_out = jt->enabled && jt->active;
		*jp->kb_jog_active = jt->kb_jog_active;
		*jp->wheel_jog_active = jt->wheel_jog_active;
		*jp->backlash_corr = jt->backlash_corr;
		*jp->backlash_filt = jt->backlash_filt;
		*jp->backlash_vel = jt->backlash_vel;
		*jp->f_error = jt->ferror;
		*jp->f_error_lim = jt->ferror_limit;
		*jp->f_errored = jt->ferrored;
		*jp->free_pos_cmd = jt->free.pos_cmd;
		*jp->free_vel_lim = jt->free.max_vel;
		*jp->free_tp_enable = jt->free.enable;
		*jp->in_position = jt->inpos;
		*jp->pos_hard_limit = jt->on_pos_limit;
		*jp->neg_hard_limit = jt->on_neg_limit;
		*jp->active = jt->active;
		*jp->error = jt->error;
		*jp->faulted = jt->fault;
	}
}
