/* SPDX-License-Identifier: GPL-2.0-or-later */
/* command_fp.c - motion-command-handler (motion.md 3, 7): takes at most one new
 * command from the shared slot per period, checks it (cmdcheck.h, then the state
 * preconditions of motion.md 7.1 with their messages) and runs it. FP: commands
 * carry doubles. */
#include "motmod_priv.h"
#include "cmdcheck.h"
#include "coord.h"
#include "rtapi_math.h"

static double clamp(double v, double lo, double hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

/* A jog's limits for joint j: soft limits once homed, else pos_fb +- the joint's
 * range (motion.md 11.2). */
bool mot_joint_jog_limits(struct motmod *m, int j, double *lo, double *hi)
{
	struct mot_joint *jt = &m->joint[j];
	double range = jt->max_limit - jt->min_limit;

	if (get_homed(j)) {
		*lo = jt->min_limit;
		*hi = jt->max_limit;
		return true;
	}
	*lo = jt->pos_fb - range;
	*hi = jt->pos_fb + range;
	return false;
}

/* Common jog preconditions (motion.md 7.1 "Jog preconditions"); true when allowed. */
static bool jog_allowed(struct motmod *m, const char *what)
{
	if (!m->enabled) {
		mot_error(m, "Can't jog %s when not enabled.", what);
		return false;
	}
	if (*m->pins->jog_inhibit) {
		mot_error(m, "Can't jog %s while motion.jog-inhibit is TRUE.", what);
		return false;
	}
	if (get_homing_is_active()) {
		mot_error(m, "Can't jog any joints while homing.");
		return false;
	}
	if (m->probe_tripped && !m->no_probe_jog_error && *m->pins->probe_input) {
		mot_error(m, "Can't jog %s while the probe is tripped.", what);
		return false;
	}
	return true;
}

static int joint_jog(struct motmod *m, const struct motion_command *c)
{
	int j = c->joint;
	struct mot_joint *jt = &m->joint[j];
	double lo, hi, target, dir = c->vel > 0.0 ? 1.0 : -1.0;
	unsigned int neg_bit = 1u << (2 * j), pos_bit = 2u << (2 * j);

	if (!jt->active) {
		mot_error(m, "Can't jog inactive joint %d.", j);
		return MOTION_CMD_INVALID;
	}
	if (get_home_is_synchronized(j) && !get_homed(j)) {
		mot_error(m, "Can't jog joint %d: it homes in a synchronized sequence and is not homed.", j);
		return MOTION_CMD_INVALID;
	}
	if (get_home_needs_unlock_first(j)) {
		mot_error(m, "Can't jog locking joint_num=%d", j);
		return MOTION_CMD_INVALID;
	}
	if (dir > 0.0 && jt->on_pos_limit && !(m->override_mask & pos_bit)) {
		mot_error(m, "Can't jog joint %d further past max hard limit.", j);
		return MOTION_CMD_INVALID;
	}
	if (dir < 0.0 && jt->on_neg_limit && !(m->override_mask & neg_bit)) {
		mot_error(m, "Can't jog joint %d further past min hard limit.", j);
		return MOTION_CMD_INVALID;
	}
	mot_joint_jog_limits(m, j, &lo, &hi);
	switch (c->command) {
	case MOTCMD_JOG_CONT:
		target = dir > 0.0 ? hi : lo;
		break;
	case MOTCMD_JOG_INCR:
		target = jt->free.pos_cmd + dir * c->offset;
		break;
	default:	/* JOG_ABS */
		target = c->offset;
		break;
	}
	jt->free.pos_cmd = clamp(target, lo, hi);
	jt->free.max_vel = rtapi_fmin(rtapi_fabs(c->vel), jt->vel_limit);
	jt->free.max_acc = jt->acc_limit;
	jt->free.enable = true;
	jt->kb_jog_active = true;
	jt->wheel_jog_active = false;
	jt->was_on_limit = jt->on_pos_limit || jt->on_neg_limit;
	return MOTION_CMD_OK;
}

static int axis_jog(struct motmod *m, const struct motion_command *c)
{
	struct mot_axis *ax = &m->axis[c->axis];
	double dir = c->vel > 0.0 ? 1.0 : -1.0, target;

	switch (c->command) {
	case MOTCMD_JOG_CONT:
		target = dir > 0.0 ? ax->max_limit : ax->min_limit;
		break;
	case MOTCMD_JOG_INCR:
		target = ax->tp.pos_cmd + dir * c->offset;
		break;
	default:
		target = c->offset;
		break;
	}
	ax->tp.pos_cmd = clamp(target, ax->min_limit, ax->max_limit);
	ax->tp.max_vel = rtapi_fmin(rtapi_fabs(c->vel), ax->vel_limit);
	ax->tp.max_acc = ax->acc_limit;
	ax->tp.enable = true;
	ax->kb_jog_active = true;
	ax->wheel_jog_active = false;
	return MOTION_CMD_OK;
}

static int jog(struct motmod *m, const struct motion_command *c)
{
	if (c->command == MOTCMD_JOG_ABORT) {
		if (m->state == MOTION_TELEOP) {
			m->axis[c->axis].tp.enable = false;
			m->axis[c->axis].kb_jog_active = false;
		} else {
			m->joint[c->joint].free.enable = false;
			m->joint[c->joint].kb_jog_active = false;
		}
		return MOTION_CMD_OK;
	}
	if (m->state == MOTION_TELEOP) {
		if (!jog_allowed(m, "axis"))
			return MOTION_CMD_INVALID;
		return axis_jog(m, c);
	}
	if (!jog_allowed(m, "joint"))
		return MOTION_CMD_INVALID;
	if (m->state != MOTION_FREE) {
		mot_error(m, "Can't jog joint %d: not in joint mode (motion state %d).", c->joint,
			  m->state);
		return MOTION_CMD_INVALID;
	}
	return joint_jog(m, c);
}

static void abort_axis_jogs(struct motmod *m)
{
	int l;

	for (l = 0; l < MOTION_MAX_AXES; l++) {
		m->axis[l].tp.enable = false;
		m->axis[l].kb_jog_active = false;
		m->axis[l].wheel_jog_active = false;
	}
}

static int home(struct motmod *m, const struct motion_command *c)
{
	int r;

	if (m->state != MOTION_FREE && m->enabled) {
		mot_error(m, "must be in joint mode to home");
		return MOTION_CMD_INVALID;
	}
	if (*m->pins->homing_inhibit) {
		mot_error(m, "Homing denied by motion.homing-inhibit joint=%d", c->joint);
		return MOTION_CMD_INVALID;
	}
	if (!m->enabled)	/* silently ignored (motion.md 7.1) */
		return MOTION_CMD_OK;
	r = do_home_joint(c->joint);
	return r < 0 ? MOTION_CMD_BAD_EXEC : MOTION_CMD_OK;
}

static int unhome(struct motmod *m, const struct motion_command *c)
{
	if (m->state != MOTION_FREE && m->state != MOTION_DISABLED) {
		mot_error(m, "must be in joint mode or disabled to unhome");
		return MOTION_CMD_INVALID;
	}
	return set_unhomed(c->joint, m->state) < 0 ? MOTION_CMD_BAD_EXEC : MOTION_CMD_OK;
}

static int comp_point(struct motmod *m, const struct motion_command *c)
{
	int r = comp_table_add(&m->joint[c->joint].comp, c->comp_nominal, c->comp_forward,
			       c->comp_reverse);

	if (r == COMP_ADD_FULL)
		mot_error(m, "joint %d: too many compensation entries", c->joint);
	else if (r == COMP_ADD_ORDER)
		mot_error(m, "joint %d: compensation values must increase", c->joint);
	else if (r != COMP_ADD_OK)
		mot_error(m, "joint %d: compensation entry out of range", c->joint);
	return r == COMP_ADD_OK ? MOTION_CMD_OK : MOTION_CMD_INVALID_PARAMS;
}

/* SET_LINE / SET_CIRCLE / PROBE / RIGID_TAP: enabled, COORD, end point inside the
 * world limits and the joint limits (through the inverse kinematics). */
static int queue_move(struct motmod *m, const struct motion_command *c)
{
	static const char letters[] = "XYZABCUVW";
	double joints[KINS_MAX_JOINTS];
	EmcPose end;
	int l, j, r;

	if (!m->enabled || m->state != MOTION_COORD) {
		mot_error(m, "need to be enabled, in coord mode for %s move",
			  c->command == MOTCMD_SET_CIRCLE ? "circular" :
			  c->command == MOTCMD_PROBE ? "probe" :
			  c->command == MOTCMD_RIGID_TAP ? "rigid tap" : "linear");
		return MOTION_CMD_INVALID;
	}
	for (l = 0; l < MOTION_MAX_AXES; l++) {
		if (c->pos.v[l] > m->axis[l].max_limit || c->pos.v[l] < m->axis[l].min_limit) {
			mot_error(m, "%s move on line %d would exceed %c's %s limit",
				  c->command == MOTCMD_SET_CIRCLE ? "Circular" : "Linear", c->id,
				  letters[l], c->pos.v[l] > m->axis[l].max_limit ? "positive" : "negative");
			return MOTION_CMD_INVALID_PARAMS;
		}
	}
	mot_array_to_pose(c->pos.v, &end);
	for (j = 0; j < KINS_MAX_JOINTS; j++)
		joints[j] = j < m->num_joints ? m->joint[j].pos_cmd : 0.0;
	if (mot_inverse(m, &end, joints) == 0) {
		for (j = 0; j < m->num_joints - m->num_extrajoints; j++) {
			struct mot_joint *jt = &m->joint[j];

			if (!jt->active || !get_homed(j))
				continue;
			if (joints[j] > jt->max_limit || joints[j] < jt->min_limit) {
				mot_error(m, "%s move on line %d would exceed joint %d's %s limit",
					  c->command == MOTCMD_SET_CIRCLE ? "Circular" : "Linear", c->id, j,
					  joints[j] > jt->max_limit ? "positive" : "negative");
				return MOTION_CMD_INVALID_PARAMS;
			}
		}
	}
	if (c->command == MOTCMD_PROBE) {
		bool in = *m->pins->probe_input;

		if (!(c->probe_type & 2) && in) {
			mot_error(m, "Probe is already tripped when starting G38.2 or G38.3 move");
			return MOTION_CMD_INVALID;
		}
		if ((c->probe_type & 2) && !in) {
			mot_error(m, "Probe is not tripped when starting G38.4 or G38.5 move");
			return MOTION_CMD_INVALID;
		}
	}
	switch (c->command) {
	case MOTCMD_SET_CIRCLE:
		r = coord_add_circle(m, c);
		break;
	case MOTCMD_RIGID_TAP:
		r = coord_add_rigid_tap(m, c);
		break;
	default:
		r = coord_add_line(m, c, c->command == MOTCMD_PROBE);
		break;
	}
	if (r == -ENOSPC) {
		mot_error(m, "motion queue is full: move on line %d refused", c->id);
		return MOTION_CMD_BAD_EXEC;
	}
	if (r) {
		mot_error(m, "can't add %s move on line %d (planner refused it)",
			  cmdcheck_name(c->command), c->id);
		return MOTION_CMD_BAD_EXEC;
	}
	if (c->command == MOTCMD_PROBE) {
		m->probing = true;
		m->probe_tripped = false;
		m->probe_type = c->probe_type;
	}
	return MOTION_CMD_OK;
}

static void spindle_on(struct motmod *m, int s, const struct motion_command *c)
{
	struct mot_spindle *sp = &m->spindle[s];

	sp->speed = c->vel;
	sp->css_factor = c->css_factor;
	sp->xoffset = c->xoffset;
	sp->state = 1;
	sp->direction = c->vel > 0.0 ? 1 : c->vel < 0.0 ? -1 : 0;
	sp->brake = 0;
	sp->locked = 0;
	sp->orient_state = 0;
	*m->pins->spindle[s].orient = 0;
	if (c->wait_for_at_speed)
		m->atspeed_next_feed = true;
}

static void spindle_off(struct motmod *m, int s)
{
	struct mot_spindle *sp = &m->spindle[s];

	sp->speed = 0.0;
	sp->state = 0;
	sp->direction = 0;
	sp->brake = 1;
	sp->locked = 0;
	sp->orient_state = 0;
	sp->css_factor = 0.0;
	*m->pins->spindle[s].orient = 0;
}

static void spindle_orient(struct motmod *m, int s, const struct motion_command *c)
{
	struct mot_spindle *sp = &m->spindle[s];

	sp->speed = 0.0;
	sp->state = 0;
	sp->direction = 0;
	sp->brake = 0;
	sp->locked = 0;
	sp->orient_angle = c->orientation;
	sp->orient_mode = c->mode;
	sp->orient_state = 1;	/* in progress */
	*m->pins->spindle[s].orient = 1;
}

static void spindle_step(struct motmod *m, int s, double sign)
{
	struct mot_spindle *sp = &m->spindle[s];

	if (sp->speed > 0.0 || (sp->speed == 0.0 && sign > 0.0 && sp->direction >= 0))
		sp->speed = rtapi_fmax(0.0, sp->speed + sign * sp->increment);
	else if (sp->speed < 0.0)
		sp->speed = rtapi_fmin(0.0, sp->speed - sign * sp->increment);
}

/* Spindle commands for spindle c->spindle, or every spindle for -1. */
static int spindle_cmd(struct motmod *m, const struct motion_command *c)
{
	int s, first = c->spindle < 0 ? 0 : c->spindle;
	int last = c->spindle < 0 ? m->num_spindles - 1 : c->spindle;

	if (m->num_spindles == 0 || c->spindle >= m->num_spindles) {
		mot_error(m, "Attempt to %s non-existent spindle %d",
			  c->command == MOTCMD_SPINDLE_ON ? "start" : "use", c->spindle);
		return MOTION_CMD_INVALID_PARAMS;
	}
	for (s = first; s <= last; s++) {
		struct mot_spindle *sp = &m->spindle[s];

		switch (c->command) {
		case MOTCMD_SPINDLE_ON:
			spindle_on(m, s, c);
			break;
		case MOTCMD_SPINDLE_OFF:
			spindle_off(m, s);
			break;
		case MOTCMD_SPINDLE_ORIENT:
			spindle_orient(m, s, c);
			break;
		case MOTCMD_SPINDLE_INCREASE:
			spindle_step(m, s, 1.0);
			break;
		case MOTCMD_SPINDLE_DECREASE:
			spindle_step(m, s, -1.0);
			break;
		case MOTCMD_SPINDLE_BRAKE_ENGAGE:
			sp->brake = 1;
			break;
		case MOTCMD_SPINDLE_BRAKE_RELEASE:
			sp->brake = 0;
			break;
		case MOTCMD_SPINDLE_SCALE:
			sp->scale = rtapi_fmax(0.0, c->scale);
			break;
		default:	/* SET_SPINDLE_PARAMS */
			sp->min_fwd = c->spindle_params[0];
			sp->max_fwd = c->spindle_params[1];
			sp->min_rev = c->spindle_params[2];
			sp->max_rev = c->spindle_params[3];
			sp->increment = c->spindle_params[4];
			break;
		}
	}
	return MOTION_CMD_OK;
}

static void set_enable_bit(struct motmod *m, int bit, int on)
{
	if (on)
		m->enables_new |= bit;
	else
		m->enables_new &= ~bit;
}

/* Run one checked command; returns its commandStatus. */
static int run(struct motmod *m, const struct motion_command *c)
{
	int j;

	switch (c->command) {
	case MOTCMD_ABORT:
		if (m->state == MOTION_TELEOP) {
			abort_axis_jogs(m);
		} else if (m->state == MOTION_COORD) {
			coord_abort(m);
		} else {
			for (j = 0; j < m->num_joints; j++) {
				m->joint[j].free.enable = false;
				m->joint[j].kb_jog_active = false;
				m->joint[j].wheel_jog_active = false;
			}
			do_cancel_homing(-1);
		}
		m->error = false;
		for (j = 0; j < m->num_joints; j++)
			m->joint[j].error = m->joint[j].fault = false;
		m->paused = false;
		return MOTION_CMD_OK;
	case MOTCMD_ENABLE:
		if (!*m->pins->enable) {
			mot_error(m, "can't enable motion, enable input is false");
			return MOTION_CMD_INVALID;
		}
		m->enable_req = true;
		m->disable_req = false;
		return MOTION_CMD_OK;
	case MOTCMD_DISABLE:
		m->disable_req = true;
		m->enable_req = false;
		return MOTION_CMD_OK;
	case MOTCMD_PAUSE:
		coord_pause(m);
		m->paused = true;
		return MOTION_CMD_OK;
	case MOTCMD_RESUME:
		coord_resume(m);
		m->paused = false;
		m->stepping = false;
		return MOTION_CMD_OK;
	case MOTCMD_STEP:
		if (coord_step(m)) {
			mot_error(m, "MOTION: can't STEP while already executing");
			return MOTION_CMD_INVALID;
		}
		m->stepping = true;
		return MOTION_CMD_OK;
	case MOTCMD_REVERSE:
		/* the planner cannot run the path backwards (docs/motion.md, Not done) */
		mot_error(m, "reverse run is not supported");
		return MOTION_CMD_INVALID;
	case MOTCMD_FORWARD:
		return MOTION_CMD_OK;	/* the only direction there is */
	case MOTCMD_FREE:
		abort_axis_jogs(m);
		m->free_req = true;
		m->coord_req = m->teleop_req = false;
		return MOTION_CMD_OK;
	case MOTCMD_COORD:
	case MOTCMD_TELEOP:
		if (m->kins_type != KINEMATICS_IDENTITY && !mot_all_homed(m)) {
			mot_error(m, "all joints must be homed before going into %s mode",
				  c->command == MOTCMD_COORD ? "coordinated" : "teleop");
			return MOTION_CMD_INVALID;
		}
		m->coord_req = c->command == MOTCMD_COORD;
		m->teleop_req = c->command == MOTCMD_TELEOP;
		m->free_req = false;
		return MOTION_CMD_OK;
	case MOTCMD_SPINDLE_SCALE:
	case MOTCMD_SPINDLE_ON:
	case MOTCMD_SPINDLE_OFF:
	case MOTCMD_SPINDLE_INCREASE:
	case MOTCMD_SPINDLE_DECREASE:
	case MOTCMD_SPINDLE_BRAKE_ENGAGE:
	case MOTCMD_SPINDLE_BRAKE_RELEASE:
	case MOTCMD_SPINDLE_ORIENT:
	case MOTCMD_SET_SPINDLE_PARAMS:
		return spindle_cmd(m, c);
	case MOTCMD_SS_ENABLE:
		set_enable_bit(m, MOTION_SS_ENABLED, c->mode);
		return MOTION_CMD_OK;
	case MOTCMD_FS_ENABLE:
		set_enable_bit(m, MOTION_FS_ENABLED, c->mode);
		return MOTION_CMD_OK;
	case MOTCMD_AF_ENABLE:
		set_enable_bit(m, MOTION_AF_ENABLED, c->mode);
		return MOTION_CMD_OK;
	case MOTCMD_FH_ENABLE:
		set_enable_bit(m, MOTION_FH_ENABLED, c->mode);
		return MOTION_CMD_OK;
	case MOTCMD_FEED_SCALE:
		m->feed_scale = rtapi_fmax(0.0, c->scale);
		return MOTION_CMD_OK;
	case MOTCMD_RAPID_SCALE:
		m->rapid_scale = rtapi_fmax(0.0, c->scale);
		return MOTION_CMD_OK;
	case MOTCMD_OVERRIDE_LIMITS:
		if (c->joint < 0) {
			m->override_mask = 0;
			return MOTION_CMD_OK;
		}
		if (m->joint[c->joint].on_neg_limit)
			m->override_mask |= 1u << (2 * c->joint);
		if (m->joint[c->joint].on_pos_limit)
			m->override_mask |= 2u << (2 * c->joint);
		return MOTION_CMD_OK;
	case MOTCMD_SET_LINE:
	case MOTCMD_SET_CIRCLE:
	case MOTCMD_PROBE:
	case MOTCMD_RIGID_TAP:
		return queue_move(m, c);
	case MOTCMD_SET_TELEOP_VECTOR:
		mot_error(m, "SET_TELEOP_VECTOR is EMC2's teleop jog: use JOG_CONT with an axis");
		return MOTION_CMD_INVALID;
	case MOTCMD_CLEAR_PROBE_FLAGS:
		m->probe_tripped = false;
		return MOTION_CMD_OK;
	case MOTCMD_SET_VEL:
		m->traj_vel = c->vel;
		coord_set_limits(m);
		return MOTION_CMD_OK;
	case MOTCMD_SET_VEL_LIMIT:
		m->traj_vel_limit = c->vel;
		coord_set_limits(m);
		return MOTION_CMD_OK;
	case MOTCMD_SET_ACC:
		m->traj_acc = c->acc;
		coord_set_limits(m);
		return MOTION_CMD_OK;
	case MOTCMD_SET_MAX_FEED_OVERRIDE:
		m->max_feed_scale = c->scale;
		coord_set_limits(m);
		return MOTION_CMD_OK;
	case MOTCMD_SET_TERM_COND:
		m->term_cond = c->termCond;
		m->tolerance = c->tolerance;
		coord_set_term_cond(m, c->termCond, c->tolerance);
		return MOTION_CMD_OK;
	case MOTCMD_SET_SPINDLESYNC:
		coord_set_spindlesync(m, c->spindle, c->spindlesync, c->flags != 0);
		return MOTION_CMD_OK;
	case MOTCMD_SET_NUM_JOINTS:
	case MOTCMD_SET_NUM_SPINDLES:
		if (c->command == MOTCMD_SET_NUM_SPINDLES && c->count > m->num_spindles) {
			mot_error(m, "%d spindles requested, motmod was loaded with num_spindles=%d: using %d",
				  c->count, m->num_spindles, m->num_spindles);
		}
		return MOTION_CMD_OK;
	case MOTCMD_SET_WORLD_HOME:
		mot_array_to_pose(c->pos.v, &m->world_home);
		return MOTION_CMD_OK;
	case MOTCMD_SET_DEBUG:
		*m->pins->debug_s32 = c->count;
		return MOTION_CMD_OK;
	case MOTCMD_SET_DOUT:
		if (c->now) {
			m->dout_state[c->out] = c->start ? 1 : 0;
			return MOTION_CMD_OK;
		}
		return coord_set_dout(m, c->out, c->start, c->end) ? MOTION_CMD_BAD_EXEC : MOTION_CMD_OK;
	case MOTCMD_SET_AOUT:
		if (c->now) {
			m->aout_value[c->out] = c->aout_start;
			return MOTION_CMD_OK;
		}
		return coord_set_aout(m, c->out, c->aout_start, c->aout_end) ? MOTION_CMD_BAD_EXEC :
									       MOTION_CMD_OK;
	case MOTCMD_SET_OFFSET:
		m->tool_offset = c->pos;
		return MOTION_CMD_OK;
	case MOTCMD_SETUP_ARC_BLENDS:
		return coord_set_arc_blend(m, c) ? MOTION_CMD_INVALID_PARAMS : MOTION_CMD_OK;
	case MOTCMD_ENABLE_WATCHDOG:
	case MOTCMD_DISABLE_WATCHDOG:
	case MOTCMD_JOINT_ENABLE_AMPLIFIER:
	case MOTCMD_JOINT_DISABLE_AMPLIFIER:
		return MOTION_CMD_OK;	/* legacy: amp-enable follows the joint's ENABLE */
	case MOTCMD_SET_PROBE_ERR_INHIBIT:
		m->no_probe_jog_error = c->mode & 1;
		m->no_probe_home_error = (c->mode & 2) != 0;
		return MOTION_CMD_OK;
	case MOTCMD_JOG_CONT:
	case MOTCMD_JOG_INCR:
	case MOTCMD_JOG_ABS:
	case MOTCMD_JOG_ABORT:
		return jog(m, c);
	case MOTCMD_JOINT_ACTIVATE:
		m->joint[c->joint].active = true;
		return MOTION_CMD_OK;
	case MOTCMD_JOINT_DEACTIVATE:
		m->joint[c->joint].active = false;
		return MOTION_CMD_OK;
	case MOTCMD_JOINT_HOME:
		return home(m, c);
	case MOTCMD_JOINT_UNHOME:
		return unhome(m, c);
	case MOTCMD_SET_JOINT_POSITION_LIMITS:
		m->joint[c->joint].min_limit = c->minLimit;
		m->joint[c->joint].max_limit = c->maxLimit;
		return MOTION_CMD_OK;
	case MOTCMD_SET_JOINT_BACKLASH:
		m->joint[c->joint].backlash = c->value;
		return MOTION_CMD_OK;
	case MOTCMD_SET_JOINT_MIN_FERROR:
		m->joint[c->joint].min_ferror = c->value;
		return MOTION_CMD_OK;
	case MOTCMD_SET_JOINT_MAX_FERROR:
		m->joint[c->joint].max_ferror = c->value;
		return MOTION_CMD_OK;
	case MOTCMD_SET_JOINT_VEL_LIMIT:
		m->joint[c->joint].vel_limit = c->value;
		return MOTION_CMD_OK;
	case MOTCMD_SET_JOINT_ACC_LIMIT:
		m->joint[c->joint].acc_limit = c->value;
		return MOTION_CMD_OK;
	case MOTCMD_SET_JOINT_HOMING_PARAMS:
		set_joint_homing_params(c->joint, c->offset, c->home, c->home_final_vel, c->search_vel,
					c->latch_vel, c->flags, c->home_sequence, c->volatile_home != 0);
		return MOTION_CMD_OK;
	case MOTCMD_UPDATE_JOINT_HOMING_PARAMS:
		update_joint_homing_params(c->joint, c->offset, c->home, c->home_sequence);
		return MOTION_CMD_OK;
	case MOTCMD_SET_JOINT_MOTOR_OFFSET:
		m->joint[c->joint].motor_offset = c->offset;
		return MOTION_CMD_OK;
	case MOTCMD_SET_JOINT_COMP:
		return comp_point(m, c);
	case MOTCMD_SET_AXIS_POSITION_LIMITS:
		m->axis[c->axis].min_limit = c->minLimit;
		m->axis[c->axis].max_limit = c->maxLimit;
		return MOTION_CMD_OK;
	case MOTCMD_SET_AXIS_VEL_LIMIT:
		m->axis[c->axis].vel_limit = c->value;
		coord_set_limits(m);
		return MOTION_CMD_OK;
	case MOTCMD_SET_AXIS_ACC_LIMIT:
		m->axis[c->axis].acc_limit = c->value;
		coord_set_limits(m);
		return MOTION_CMD_OK;
	case MOTCMD_SET_AXIS_LOCKING_JOINT:
		m->axis[c->axis].locking_joint = c->joint;
		return MOTION_CMD_OK;
	case MOTCMD_SET_AXIS_EXT_OFFSET_LIMITS:
		m->axis[c->axis].eoff_vel = c->vel;
		m->axis[c->axis].eoff_acc = c->acc;
		return MOTION_CMD_OK;
	default:
		return MOTION_CMD_UNKNOWN;
	}
}

void mot_command_handler(void *arg, long period_ns)
{
	struct motmod *m = arg;
	struct motion_shmem *shm = m->shm;
	struct motion_command c;
	struct cmdcheck_config cfg;
	char why[MOTION_ERR_LEN - 64];
	rtapi_u32 num = __atomic_load_n(&shm->command.commandNum, __ATOMIC_ACQUIRE);
	int status;

	(void)period_ns;
	if (num == m->last_cmd_num)
		return;
	/* the copy is what gets checked and run, whatever the writer does meanwhile */
	memcpy(&c, (const void *)&shm->command, sizeof(c));
	c.commandNum = num;
	if (num != m->last_cmd_num + 1) {
		mot_error(m, "command number %u out of sequence (expected %u): ignored", num,
			  m->last_cmd_num + 1);
		status = MOTION_CMD_INVALID;
	} else {
		cfg.num_joints = m->num_joints;
		cfg.num_spindles = m->num_spindles;
		cfg.num_dout = m->num_dout;
		cfg.num_aout = m->num_aout;
		cfg.teleop = m->state == MOTION_TELEOP;
		status = cmdcheck(&c, &cfg, why, sizeof(why));
		if (status == MOTION_CMD_UNKNOWN)
			mot_error(m, "%s", why);
		else if (status != MOTION_CMD_OK)
			mot_error(m, "%s: %s", cmdcheck_name(c.command), why);
		else
			status = run(m, &c);
	}
	m->last_cmd_num = num;
	shm->status.commandEcho = c.command;
	shm->status.commandStatus = status;
	__atomic_store_n(&shm->status.commandNumEcho, num, __ATOMIC_RELEASE);
}
