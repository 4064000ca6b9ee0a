/* SPDX-License-Identifier: GPL-2.0-or-later */
/* control_fp.c - motion-controller: the per-period cycle in the order of motion.md 3
 * (timing, homing inputs, kinematics switch, inputs, forward kinematics, probe,
 * faults, operating mode, jog wheels, homing, setpoints, compensation, outputs,
 * homing outputs, status). The per-joint and spindle parts are in joints_fp.c and
 * spindle_fp.c, coordinated motion behind coord.h. */
#include "motmod_priv.h"
#include "coord.h"
#include "rtapi_math.h"

void mot_pose_to_array(const EmcPose *p, double *v)
{
	v[0] = p->tran.x;
	v[1] = p->tran.y;
	v[2] = p->tran.z;
	v[3] = p->a;
	v[4] = p->b;
	v[5] = p->c;
	v[6] = p->u;
	v[7] = p->v;
	v[8] = p->w;
}

void mot_array_to_pose(const double *v, EmcPose *p)
{
	p->tran.x = v[0];
	p->tran.y = v[1];
	p->tran.z = v[2];
	p->a = v[3];
	p->b = v[4];
	p->c = v[5];
	p->u = v[6];
	p->v = v[7];
	p->w = v[8];
}

int mot_forward(struct motmod *m, const double *joints, EmcPose *world)
{
	double v[MOTION_MAX_AXES];
	int r = m->kins.forward(joints, world, &m->fflags, &m->iflags), l;

	if (r < 0)
		return r;
	mot_pose_to_array(world, v);
	for (l = 0; l < MOTION_MAX_AXES; l++)
		if (!rtapi_isfinite(v[l]))
			return -EINVAL;
	return 0;
}

/* joints[] holds the current joints on entry; a non-finite result is a failure */
int mot_inverse(struct motmod *m, const EmcPose *world, double *joints)
{
	int r = m->kins.inverse(world, joints, &m->iflags, &m->fflags), j;

	if (r < 0)
		return r;
	for (j = 0; j < m->num_joints; j++)
		if (!rtapi_isfinite(joints[j]))
			return -EINVAL - 1000 - j;	/* caller names joint j */
	return 0;
}

static void joints_of(struct motmod *m, double *joints, bool feedback)
{
	int j;

	for (j = 0; j < KINS_MAX_JOINTS; j++)
		joints[j] = j < m->num_joints ? (feedback ? m->joint[j].pos_fb : m->joint[j].pos_cmd) : 0.0;
}

/* 2.9 process_inputs: the net feed scale (motion.md 3 step 4, 10.1) */
static void feed_scales(struct motmod *m, double *feed, double *rapid)
{
	struct mot_pins *p = m->pins;
	double scale_feed = 1.0, scale_rapid = 1.0, adaptive;

	if (m->enables_new & MOTION_FS_ENABLED) {
		scale_feed = m->feed_scale;
		scale_rapid = m->rapid_scale;
	}
	if (m->enables_new & MOTION_AF_ENABLED) {
		adaptive = *p->adaptive_feed;
		if (!rtapi_isfinite(adaptive))
			adaptive = 0.0;
		adaptive = rtapi_fmax(-1.0, rtapi_fmin(1.0, adaptive));
		scale_feed *= adaptive;
	}
	if (((m->enables_new & MOTION_FH_ENABLED) && *p->feed_hold) || *p->feed_inhibit) {
		scale_feed = 0.0;
		scale_rapid = 0.0;
	}
	*feed = scale_feed;
	*rapid = scale_rapid;
}

/* every active joint homed (motion.is-all-homed); computed here from get_homed() so
 * it holds from the first period on */
bool mot_all_homed(struct motmod *m)
{
	int j;

	for (j = 0; j < m->num_joints; j++)
		if (m->joint[j].active && !get_homed(j))
			return false;
	return true;
}

static void forward_kins(struct motmod *m)
{
	double joints[KINS_MAX_JOINTS];
	EmcPose fb = m->world_fb;

	if (m->kins_type != KINEMATICS_IDENTITY && !mot_all_homed(m)) {
		m->world_fb_ok = false;
		return;
	}
	joints_of(m, joints, true);
	m->world_fb_ok = mot_forward(m, joints, &fb) == 0;
	if (m->world_fb_ok)
		m->world_fb = fb;
}

/* switchable kinematics: motion.switchkins-type changed (motion.md 3 step 3) */
static void switch_kins(struct motmod *m)
{
	double t = *m->pins->switchkins_type, joints[KINS_MAX_JOINTS];
	EmcPose w = m->world_cmd;

	if (t == m->switchkins_prev || !m->kins.switchable())
		return;
	m->switchkins_prev = t;
	if (m->kins.switch_to((int)t) < 0) {
		mot_error(m, "kinematicsSwitch(%d) failed", (int)t);
		return;
	}
	joints_of(m, joints, false);
	if (mot_forward(m, joints, &w) == 0) {
		m->world_cmd = w;
		coord_set_position(m, &w);
	}
}

/* motion.md 13 */
static void probe_inputs(struct motmod *m)
{
	bool in = *m->pins->probe_input;
	bool rising = in && !m->probe_prev;
	int j, l;

	m->probe_prev = in;
	if (m->probing)
		return;		/* the planner tests the level of a probe move (coord_cycle) */
	if (!rising)
		return;
	if (m->state == MOTION_COORD && !coord_is_done(m)) {
		coord_abort(m);
		mot_error(m, "Probe tripped during non-probe move.");
		return;
	}
	if (homing_probe_trip(m->no_probe_home_error))
		return;
	if (m->no_probe_jog_error)
		return;
	for (j = 0; j < m->num_joints; j++) {
		if (m->joint[j].kb_jog_active || m->joint[j].wheel_jog_active) {
			m->joint[j].free.enable = false;
			m->joint[j].kb_jog_active = m->joint[j].wheel_jog_active = false;
			mot_error(m, "Probe tripped during a joint jog.");
		}
	}
	for (l = 0; l < MOTION_MAX_AXES; l++) {
		if (m->axis[l].kb_jog_active || m->axis[l].wheel_jog_active) {
			m->axis[l].tp.enable = false;
			m->axis[l].kb_jog_active = m->axis[l].wheel_jog_active = false;
			mot_error(m, "Probe tripped during a coordinate jog.");
		}
	}
}

static void check_faults(struct motmod *m)
{
	struct mot_pins *p = m->pins;
	int i;

	if (!m->enabled)
		return;
	if (!*p->enable) {
		mot_error(m, "motion stopped by enable input");
		m->disable_req = true;
	}
	for (i = 0; i < m->num_misc_error; i++) {
		if (*p->misc_error[i]) {
			mot_error(m, "Motion Stopped by misc error %d", i);
			m->disable_req = true;
		}
	}
	mot_check_joint_faults(m);
}

static void reset_free_planners(struct motmod *m)
{
	int j;

	for (j = 0; j < m->num_joints; j++) {
		freetp_reset(&m->joint[j].free, m->joint[j].pos_cmd);
		m->joint[j].kb_jog_active = m->joint[j].wheel_jog_active = false;
	}
}

static void reset_axis_planners(struct motmod *m)
{
	double v[MOTION_MAX_AXES];
	int l;

	mot_pose_to_array(&m->world_cmd, v);
	for (l = 0; l < MOTION_MAX_AXES; l++) {
		freetp_reset(&m->axis[l].tp, v[l]);
		m->axis[l].kb_jog_active = m->axis[l].wheel_jog_active = false;
	}
}

/* motion.md 6 transition rules */
static void set_operating_mode(struct motmod *m)
{
	int j;

	if (m->disable_req) {
		m->disable_req = false;
		m->enable_req = false;
		if (m->enabled) {
			coord_clear(m);
			for (j = 0; j < m->num_joints; j++) {
				m->joint[j].free.enable = false;
				m->joint[j].enabled = false;
				m->joint[j].kb_jog_active = m->joint[j].wheel_jog_active = false;
			}
			do_cancel_homing(-1);
			reset_axis_planners(m);
			m->enabled = m->coord = m->teleop = false;
			m->free_req = m->teleop_req = m->coord_req = false;
		}
	}
	if (m->enable_req) {
		m->enable_req = false;
		if (!m->enabled) {
			reset_free_planners(m);
			for (j = 0; j < m->num_joints; j++) {
				if (m->joint[j].active)
					m->joint[j].enabled = true;
				m->joint[j].error = m->joint[j].fault = false;
				m->joint[j].limit_reported = false;
			}
			coord_set_position(m, &m->world_cmd);
			do_cancel_homing(-1);
			m->enabled = true;
			m->error = false;
			m->soft_limit_reported = false;
		}
	}
	if (m->enabled && (m->free_req || m->teleop_req || m->coord_req)) {
		/* switches happen only in position; otherwise dropped (motion.md 6) */
		if (m->inpos) {
			if (m->free_req && (m->coord || m->teleop)) {
				reset_free_planners(m);
				coord_clear(m);
				m->coord = m->teleop = false;
			} else if (m->teleop_req && !m->teleop) {
				reset_axis_planners(m);
				reset_free_planners(m);
				m->teleop = true;
				m->coord = false;
			} else if (m->coord_req && !m->coord) {
				m->override_mask = 0;
				coord_set_position(m, &m->world_cmd);
				m->coord = true;
				m->teleop = false;
			}
		}
		m->free_req = m->teleop_req = m->coord_req = false;
	}
	m->state = !m->enabled ? MOTION_DISABLED : m->teleop ? MOTION_TELEOP :
		   m->coord ? MOTION_COORD : MOTION_FREE;
}

/* homing, FREE state only (motion.md 3 step 10, homing.h call order 5) */
static void run_homing(struct motmod *m)
{
	int j;

	for (j = 0; j < m->num_joints; j++) {
		struct mot_joint *jt = &m->joint[j];
		struct homing_joint *h = &m->hj[j];

		h->active = jt->active;
		h->enabled = jt->enabled;
		h->on_pos_limit = jt->on_pos_limit;
		h->on_neg_limit = jt->on_neg_limit;
		h->free_tp_active = jt->free.active;
		h->max_vel = jt->vel_limit;
		h->max_acc = jt->acc_limit;
		h->min_limit = jt->min_limit;
		h->max_limit = jt->max_limit;
		h->motor_pos_fb = *m->pins->joint[j].motor_pos_fb;
		h->backlash_filt = jt->backlash_filt;
		h->pos_cmd = jt->pos_cmd;
		h->pos_fb = jt->pos_fb;
		h->motor_offset = jt->motor_offset;
		h->free_pos = jt->free.curr_pos;
		h->free_pos_cmd = jt->free.pos_cmd;
		h->free_vel_lim = jt->free.max_vel;
		h->free_tp_enable = jt->free.enable;
	}
	if (do_homing(m->servo_period_ns))
		m->teleop_after_homing = true;
	/* TELEOP once homing has wound down its sequence too (the period after all
	 * joints are homed, homing still closes its Home-All sequence) */
	if (m->teleop_after_homing && !get_homing_is_active()) {
		m->teleop_after_homing = false;
		m->teleop_req = true;
	}
	for (j = 0; j < m->num_joints; j++) {
		struct mot_joint *jt = &m->joint[j];
		struct homing_joint *h = &m->hj[j];

		jt->pos_cmd = h->pos_cmd;
		jt->pos_fb = h->pos_fb;
		jt->motor_offset = h->motor_offset;
		jt->free.curr_pos = h->free_pos;
		if (get_homing(j)) {
			jt->free.pos_cmd = h->free_pos_cmd;
			jt->free.max_vel = h->free_vel_lim;
			jt->free.max_acc = jt->acc_limit;
			jt->free.enable = h->free_tp_enable;
		}
	}
}

static void set_world_from_joints(struct motmod *m)
{
	double joints[KINS_MAX_JOINTS];
	EmcPose w = m->world_cmd;

	if (m->kins_type != KINEMATICS_IDENTITY && !mot_all_homed(m))
		return;
	joints_of(m, joints, false);
	if (mot_forward(m, joints, &w) == 0)
		m->world_cmd = w;
}

/* A world command (TELEOP, COORD) plus the external offsets -> joints[] (holding the
 * current joints on entry) through the inverse kinematics; a failure disables motion
 * with motion.md 11.3's message. 0 or negative. */
int mot_world_to_joints(struct motmod *m, const EmcPose *world, double *joints)
{
	EmcPose w = *world;
	int r;

	mot_eoffset_add(m, &w);
	r = mot_inverse(m, &w, joints);
	if (r <= -EINVAL - 1000)
		mot_error(m, "kinematicsInverse gave non-finite joint location on joint %d",
			  -(r + EINVAL + 1000));
	else if (r < 0)
		mot_error(m, "kinematicsInverse failed");
	if (r < 0)
		m->disable_req = true;
	return r;
}

/* world_cmd -> joint commands (TELEOP) */
static void joints_from_world(struct motmod *m)
{
	double joints[KINS_MAX_JOINTS];
	int j, nkins = m->num_joints - m->num_extrajoints;

	joints_of(m, joints, false);
	if (mot_world_to_joints(m, &m->world_cmd, joints) < 0)
		return;
	for (j = 0; j < nkins; j++) {
		struct mot_joint *jt = &m->joint[j];

		jt->vel_cmd = (joints[j] - jt->pos_cmd) / m->servo_period_s;
		jt->pos_cmd = joints[j];
	}
}

static void teleop_planners(struct motmod *m)
{
	double v[MOTION_MAX_AXES];
	int l;

	for (l = 0; l < MOTION_MAX_AXES; l++) {
		struct mot_axis *ax = &m->axis[l];

		freetp_update(&ax->tp, m->servo_period_s);
		v[l] = ax->tp.curr_pos;
		if (!ax->tp.active)
			ax->kb_jog_active = ax->wheel_jog_active = false;
	}
	mot_array_to_pose(v, &m->world_cmd);
	joints_from_world(m);
}

/* motion.md 11.2 backup soft-limit check (homed joints) */
static void soft_limits(struct motmod *m)
{
	bool on = false;
	int j;

	for (j = 0; j < m->num_joints; j++) {
		struct mot_joint *jt = &m->joint[j];

		if (!jt->active || !get_homed(j))
			continue;
		if (jt->pos_cmd > jt->max_limit + 1e-12 || jt->pos_cmd < jt->min_limit - 1e-12) {
			on = true;
			if (!m->soft_limit_reported && m->enabled) {
				bool pos = jt->pos_cmd > jt->max_limit;

				mot_error(m, "Exceeded %s soft limit (%.5f) on joint %d",
					  pos ? "POSITIVE" : "NEGATIVE", pos ? jt->max_limit : jt->min_limit, j);
				m->error = true;
			}
		}
	}
	if (on)
		m->soft_limit_reported = true;
	else
		m->soft_limit_reported = false;
	m->on_soft_limit = on;
}

static void get_pos_cmds(struct motmod *m)
{
	int j;

	for (j = 0; j < m->num_joints; j++)
		m->joint[j].prev_vel_cmd = m->joint[j].vel_cmd;
	switch (m->state) {
	case MOTION_DISABLED:
		for (j = 0; j < m->num_joints; j++) {
			struct mot_joint *jt = &m->joint[j];

			jt->pos_cmd = jt->pos_fb;
			jt->vel_cmd = 0.0;
			freetp_reset(&jt->free, jt->pos_cmd);
		}
		set_world_from_joints(m);
		break;
	case MOTION_FREE:
		mot_free_planners(m);
		set_world_from_joints(m);
		break;
	case MOTION_TELEOP:
		teleop_planners(m);
		break;
	default: {
		EmcPose w = m->world_cmd;

		coord_cycle(m, &w);
		m->world_cmd = w;
		break;
	}
	}
	for (j = 0; j < m->num_joints; j++) {
		struct mot_joint *jt = &m->joint[j];

		jt->acc_cmd = m->state == MOTION_FREE || m->state == MOTION_DISABLED ? 0.0 :
			      (jt->vel_cmd - jt->prev_vel_cmd) / m->servo_period_s;
		if (m->state != MOTION_COORD)
			jt->coarse_pos = jt->pos_cmd;
	}
	soft_limits(m);
}

/* in position: nothing of the current state's planners is moving */
static void update_inpos(struct motmod *m)
{
	bool inpos = true;
	int j, l;

	switch (m->state) {
	case MOTION_FREE:
		for (j = 0; j < m->num_joints; j++)
			if (m->joint[j].free.active)
				inpos = false;
		break;
	case MOTION_TELEOP:
		for (l = 0; l < MOTION_MAX_AXES; l++)
			if (m->axis[l].tp.active)
				inpos = false;
		break;
	case MOTION_COORD:
		/* the planner is done and the interpolators have arrived */
		inpos = coord_is_done(m);
		for (j = 0; j < m->num_joints; j++)
			if (m->joint[j].vel_cmd != 0.0)
				inpos = false;
		break;
	default:
		break;
	}
	if (mot_eoffset_moving(m))
		inpos = false;
	m->inpos = inpos;
	/* a probe move without a trip: the probed position is where motion stopped */
	if (m->probe_pos_pending && (inpos || m->state != MOTION_COORD)) {
		m->probe_pos_pending = false;
		mot_pose_to_array(m->world_fb_ok ? &m->world_fb : &m->world_cmd, m->probed.v);
	}
	for (j = 0; j < m->num_joints; j++)
		m->joint[j].inpos = !m->joint[j].free.active;
}

static void motion_outputs(struct motmod *m)
{
	struct mot_pins *p = m->pins;
	double v[MOTION_MAX_AXES], vel, req, dtg;
	rtapi_s32 id, type;
	int l, i, active_depth;
	bool full, jog = false, eoffset = false;

	coord_status(m, &id, &type, &vel, &req, &dtg, &active_depth, &full);
	*p->motion_enabled = m->enabled;
	*p->in_position = m->inpos;
	*p->coord_mode = m->coord;
	*p->teleop_mode = m->teleop;
	*p->coord_error = m->error;
	*p->on_soft_limit = m->on_soft_limit;
	*p->is_all_homed = mot_all_homed(m);
	*p->motion_type = m->state == MOTION_COORD ? type : 0;
	*p->program_line = m->state == MOTION_COORD ? id : 0;
	*p->current_vel = m->state == MOTION_COORD ? vel : 0.0;
	*p->requested_vel = m->state == MOTION_COORD ? req : 0.0;
	*p->distance_to_go = m->state == MOTION_COORD ? dtg : 0.0;
	/* F x overrides in units/min while a feed or arc executes; machine units are
	 * taken as mm for the fixed-unit pins (motion has no units setting) */
	*p->feed_upm = (type == MOTION_TYPE_FEED || type == MOTION_TYPE_ARC) &&
		       m->state == MOTION_COORD ? req * m->net_feed_scale * 60.0 : 0.0;
	*p->feed_mm_per_minute = *p->feed_upm;
	*p->feed_mm_per_second = *p->feed_upm / 60.0;
	*p->feed_inches_per_minute = *p->feed_upm / 25.4;
	*p->feed_inches_per_second = *p->feed_upm / 25.4 / 60.0;
	for (i = 0; i < m->num_joints; i++)
		if (m->joint[i].kb_jog_active || m->joint[i].wheel_jog_active)
			jog = true;
	for (l = 0; l < MOTION_MAX_AXES; l++)
		if (m->axis[l].kb_jog_active || m->axis[l].wheel_jog_active)
			jog = true;
	*p->jog_is_active = jog;
	mot_pose_to_array(&m->world_cmd, v);
	for (l = 0; l < MOTION_MAX_AXES; l++) {
		struct mot_axis_pins *ap = &p->axis[l];
		struct mot_axis *ax = &m->axis[l];

		*p->tooloffset[l] = m->tool_offset.v[l];
		*ap->pos_cmd = v[l];
		*ap->teleop_pos_cmd = ax->tp.curr_pos;
		*ap->teleop_vel_cmd = ax->tp.curr_vel;
		*ap->teleop_vel_lim = ax->tp.max_vel;
		*ap->teleop_tp_enable = ax->tp.enable;
		*ap->kb_jog_active = ax->kb_jog_active;
		*ap->wheel_jog_active = ax->wheel_jog_active;
		*ap->eoffset = ax->eoff.curr_pos;
		*ap->eoffset_request = ax->eoff_request;
		if (ax->eoff.curr_pos != 0.0)
			eoffset = true;
	}
	*p->eoffset_active = eoffset;
	*p->eoffset_limited = m->eoffset_limited;
	for (i = 0; i < m->num_dout; i++)
		*p->dout[i] = m->dout_state[i];
	for (i = 0; i < m->num_aout; i++)
		*p->aout[i] = m->aout_value[i];
	p->debug_float[0] = m->net_feed_scale;
	coord_debug_params(m);
}

static void update_status(struct motmod *m)
{
	struct motion_status *s = &m->shm->status;
	double vel, req, dtg;
	rtapi_s32 id, type;
	int j, l, i, active_depth;
	bool full;

	coord_status(m, &id, &type, &vel, &req, &dtg, &active_depth, &full);
	s->motion_state = m->state;
	s->motionFlag = (m->enabled ? MOTION_FLAG_ENABLE : 0) | (m->inpos ? MOTION_FLAG_INPOS : 0) |
			(m->coord ? MOTION_FLAG_COORD : 0) | (m->error ? MOTION_FLAG_ERROR : 0) |
			(m->teleop ? MOTION_FLAG_TELEOP : 0);
	s->paused = m->paused;
	s->stepping = m->stepping;
	s->overrideLimitMask = m->override_mask;
	s->on_soft_limit = m->on_soft_limit;
	s->jogging_active = *m->pins->jog_is_active;
	s->enables_new = m->enables_new;
	s->all_homed = mot_all_homed(m);
	s->num_joints = m->num_joints;
	s->num_extrajoints = m->num_extrajoints;
	s->num_spindles = m->num_spindles;
	s->num_dio = m->num_dout;
	s->num_aio = m->num_aout;
	s->num_misc_error = m->num_misc_error;
	s->kinematics_type = m->kins_type;
	s->carte_pos_fb_ok = m->world_fb_ok;
	s->id = id;
	s->depth = coord_depth(m);
	s->activeDepth = active_depth;
	s->queueFull = full;
	s->motionType = type;
	s->probeVal = *m->pins->probe_input;
	s->probeTripped = m->probe_tripped;
	s->probing = m->probing;
	s->probe_type = m->probe_type;
	s->feed_scale = m->feed_scale;
	s->rapid_scale = m->rapid_scale;
	s->net_feed_scale = m->net_feed_scale;
	s->distance_to_go = dtg;
	s->current_vel = vel;
	s->requested_vel = req;
	s->vel = m->traj_vel;
	s->acc = m->traj_acc;
	s->vel_limit = m->traj_vel_limit;
	mot_pose_to_array(&m->world_cmd, s->carte_pos_cmd.v);
	mot_pose_to_array(&m->world_fb, s->carte_pos_fb.v);
	mot_pose_to_array(&m->world_home, s->world_home.v);
	s->probedPos = m->probed;
	s->tool_offset = m->tool_offset;
	for (j = 0; j < m->num_joints; j++) {
		struct mot_joint *jt = &m->joint[j];
		struct motion_joint_status *js = &s->joint[j];

		js->flag = (jt->enabled ? JOINT_FLAG_ENABLE : 0) | (jt->active ? JOINT_FLAG_ACTIVE : 0) |
			   (jt->inpos ? JOINT_FLAG_INPOS : 0) | (jt->error ? JOINT_FLAG_ERROR : 0) |
			   (jt->on_pos_limit ? JOINT_FLAG_MAX_HARD_LIMIT : 0) |
			   (jt->on_neg_limit ? JOINT_FLAG_MIN_HARD_LIMIT : 0) |
			   (jt->ferrored ? JOINT_FLAG_FERROR : 0) | (jt->fault ? JOINT_FLAG_FAULT : 0);
		js->homing = get_homing(j);
		js->homed = get_homed(j);
		js->home_state = get_home_state(j);
		js->pos_cmd = jt->pos_cmd;
		js->pos_fb = jt->pos_fb;
		js->vel_cmd = jt->vel_cmd;
		js->acc_cmd = jt->acc_cmd;
		js->ferror = jt->ferror;
		js->ferror_high_mark = jt->ferror_high_mark;
		js->ferror_limit = jt->ferror_limit;
		js->backlash = jt->backlash;
		js->min_pos_limit = jt->min_limit;
		js->max_pos_limit = jt->max_limit;
		js->min_ferror = jt->min_ferror;
		js->max_ferror = jt->max_ferror;
		js->vel_limit = jt->vel_limit;
		js->acc_limit = jt->acc_limit;
		js->motor_offset = jt->motor_offset;
		js->comp_entries = jt->comp.count;
	}
	for (l = 0; l < MOTION_MAX_AXES; l++) {
		struct motion_axis_status *as = &s->axis[l];

		as->pos_cmd = s->carte_pos_cmd.v[l];
		as->teleop_vel_cmd = m->axis[l].tp.curr_vel;
		as->min_pos_limit = m->axis[l].min_limit;
		as->max_pos_limit = m->axis[l].max_limit;
		as->vel_limit = m->axis[l].vel_limit;
		as->acc_limit = m->axis[l].acc_limit;
	}
	for (i = 0; i < m->num_spindles; i++) {
		struct mot_spindle *sp = &m->spindle[i];
		struct motion_spindle_status *ss = &s->spindle[i];

		ss->speed = sp->speed;
		ss->scale = sp->scale;
		ss->net_scale = sp->net_scale;
		ss->css_factor = sp->css_factor;
		ss->xoffset = sp->xoffset;
		ss->speed_out = sp->speed_out;
		ss->revs = *m->pins->spindle[i].revs;
		ss->speed_in = *m->pins->spindle[i].speed_in;
		ss->state = sp->state;
		ss->direction = sp->direction;
		ss->brake = sp->brake;
		ss->locked = sp->locked;
		ss->orient_fault = sp->orient_fault;
		ss->orient_state = sp->orient_state;
		ss->at_speed = *m->pins->spindle[i].at_speed;
		ss->fault = *m->pins->spindle[i].amp_fault_in;
	}
	for (i = 0; i < m->num_din; i++)
		s->synch_di[i] = *m->pins->din[i];
	for (i = 0; i < m->num_dout; i++)
		s->synch_do[i] = m->dout_state[i];
	for (i = 0; i < m->num_ain; i++)
		s->analog_input[i] = *m->pins->ain[i];
	for (i = 0; i < m->num_aout; i++)
		s->analog_output[i] = m->aout_value[i];
	for (i = 0; i < m->num_misc_error; i++)
		s->misc_error[i] = *m->pins->misc_error[i];
}

static void timing(struct motmod *m, long period_ns)
{
	long long now = rtapi_get_clocks();
	struct mot_pins *p = m->pins;

	if (m->last_clocks) {
		long long delta = now - m->last_clocks;
		rtapi_u32 last = *p->servo_last_period;

		*p->servo_last_period = (rtapi_u32)delta;
		/* a period half again as long as the one before: one missed deadline */
		if (last && delta > (long long)last + (long long)(last / 2))
			p->servo_overruns++;
	}
	m->last_clocks = now;
	*p->servo_last_period_ns = (double)period_ns;
	if (period_ns > 0 && period_ns != m->servo_period_ns) {
		m->servo_period_ns = period_ns;
		m->servo_period_s = period_ns * 1e-9;
	}
}

void mot_controller(void *arg, long period_ns)
{
	struct motmod *m = arg;
	struct motion_status *s = &m->shm->status;
	double feed, rapid;

	timing(m, period_ns);
	__atomic_store_n(&s->head, s->head + 1, __ATOMIC_RELEASE);
	read_homing_in_pins();
	switch_kins(m);
	feed_scales(m, &feed, &rapid);
	m->net_feed_scale = m->state == MOTION_FREE ? 1.0 : feed;
	m->net_rapid_scale = rapid;
	m->net_feed_scale_coord = feed;
	mot_spindle_inputs(m);
	mot_process_joint_inputs(m);
	forward_kins(m);
	probe_inputs(m);
	check_faults(m);
	set_operating_mode(m);
	/* called every period: counts turned while a wheel may not move (other mode,
	 * jog-inhibit) are dropped, not kept for later */
	mot_joint_jog_wheels(m, !*m->pins->jog_inhibit && m->state == MOTION_FREE);
	mot_axis_jog_wheels(m, !*m->pins->jog_inhibit && m->state == MOTION_TELEOP &&
				   !m->on_soft_limit);
	if (m->state == MOTION_FREE)
		run_homing(m);
	mot_eoffset_update(m);
	get_pos_cmds(m);
	update_inpos(m);
	mot_compensation(m);
	mot_joint_outputs(m);
	mot_spindle_outputs(m);
	motion_outputs(m);
	write_homing_out_pins();
	update_status(m);
	s->heartbeat++;
	__atomic_store_n(&s->tail, s->head, __ATOMIC_RELEASE);
}
