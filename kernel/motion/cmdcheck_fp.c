/* SPDX-License-Identifier: GPL-2.0-or-later */
/* cmdcheck_fp.c - field checks of one command (cmdcheck.h). FP only (finite tests). */
#include "cmdcheck.h"
#include "rtapi_math.h"

/* Every double of the slot must be finite, used by this command or not: a writer
 * fills the whole slot, so a non-finite number anywhere is garbage. */
static bool all_finite(const struct motion_command *c)
{
	const double *d = c->pos.v;
	const double *end = (const double *)(&c->spindle_params[5]);

	for (; d < end; d++)
		if (!rtapi_isfinite(*d))
			return false;
	return true;
}

static int bad(char *msg, int msglen, const char *fmt, int a, int b)
{
	rtapi_snprintf(msg, msglen, fmt, a, b);
	return MOTION_CMD_INVALID_PARAMS;
}

static int joint_ok(const struct motion_command *c, const struct cmdcheck_config *cfg, int lowest,
		    char *msg, int msglen)
{
	if (c->joint < lowest || c->joint >= cfg->num_joints)
		return bad(msg, msglen, "joint %d out of range (0..%d)", c->joint, cfg->num_joints - 1);
	return MOTION_CMD_OK;
}

static int axis_ok(const struct motion_command *c, char *msg, int msglen)
{
	if (c->axis < 0 || c->axis >= MOTION_MAX_AXES)
		return bad(msg, msglen, "axis %d out of range (0..%d)", c->axis, MOTION_MAX_AXES - 1);
	return MOTION_CMD_OK;
}

static int spindle_ok(const struct motion_command *c, const struct cmdcheck_config *cfg,
		      bool all_ok, char *msg, int msglen)
{
	if ((all_ok && c->spindle == -1) || (c->spindle >= 0 && c->spindle < cfg->num_spindles))
		return MOTION_CMD_OK;
	return bad(msg, msglen, "spindle %d out of range (0..%d)", c->spindle, cfg->num_spindles - 1);
}

static int positive(double v, const char *what, char *msg, int msglen)
{
	if (v > 0.0)
		return MOTION_CMD_OK;
	rtapi_snprintf(msg, msglen, "%s must be > 0", what);
	return MOTION_CMD_INVALID_PARAMS;
}

static int not_negative(double v, const char *what, char *msg, int msglen)
{
	if (v >= 0.0)
		return MOTION_CMD_OK;
	rtapi_snprintf(msg, msglen, "%s must not be negative", what);
	return MOTION_CMD_INVALID_PARAMS;
}

static int jog_check(const struct motion_command *c, const struct cmdcheck_config *cfg, char *msg,
		     int msglen)
{
	int r = cfg->teleop ? axis_ok(c, msg, msglen) : joint_ok(c, cfg, 0, msg, msglen);

	if (r == MOTION_CMD_OK && c->command != MOTCMD_JOG_ABORT && c->vel == 0.0) {
		rtapi_snprintf(msg, msglen, "jog velocity must not be 0");
		r = MOTION_CMD_INVALID_PARAMS;
	}
	return r;
}

int cmdcheck(const struct motion_command *c, const struct cmdcheck_config *cfg, char *msg,
	     int msglen)
{
	int r;

	msg[0] = 0;
	if (c->command < MOTCMD_ABORT || c->command > MOTCMD_LAST) {
		rtapi_snprintf(msg, msglen, "unknown command %d", c->command);
		return MOTION_CMD_UNKNOWN;
	}
	if (!all_finite(c)) {
		rtapi_snprintf(msg, msglen, "a number of the command is not finite");
		return MOTION_CMD_INVALID_PARAMS;
	}
	switch (c->command) {
	case MOTCMD_JOG_CONT:
	case MOTCMD_JOG_INCR:
	case MOTCMD_JOG_ABS:
	case MOTCMD_JOG_ABORT:
		return jog_check(c, cfg, msg, msglen);
	case MOTCMD_JOINT_HOME:
		return joint_ok(c, cfg, -1, msg, msglen);
	case MOTCMD_JOINT_UNHOME:
		return joint_ok(c, cfg, -2, msg, msglen);
	case MOTCMD_OVERRIDE_LIMITS:
		return joint_ok(c, cfg, -1, msg, msglen);
	case MOTCMD_JOINT_ACTIVATE:
	case MOTCMD_JOINT_DEACTIVATE:
	case MOTCMD_JOINT_ENABLE_AMPLIFIER:
	case MOTCMD_JOINT_DISABLE_AMPLIFIER:
	case MOTCMD_SET_JOINT_MOTOR_OFFSET:
	case MOTCMD_UPDATE_JOINT_HOMING_PARAMS:
		return joint_ok(c, cfg, 0, msg, msglen);
	case MOTCMD_SET_JOINT_HOMING_PARAMS:
		r = joint_ok(c, cfg, 0, msg, msglen);
		if (r == MOTION_CMD_OK && (c->flags & ~0xff))
			r = bad(msg, msglen, "homing flags 0x%x: unknown bits (known 0x%x)", c->flags, 0xff);
		return r;
	case MOTCMD_SET_JOINT_POSITION_LIMITS:
	case MOTCMD_SET_AXIS_POSITION_LIMITS:
		r = c->command == MOTCMD_SET_AXIS_POSITION_LIMITS ? axis_ok(c, msg, msglen) :
			joint_ok(c, cfg, 0, msg, msglen);
		if (r == MOTION_CMD_OK && c->minLimit > c->maxLimit) {
			rtapi_snprintf(msg, msglen, "minimum limit %g is above maximum limit %g",
				       c->minLimit, c->maxLimit);
			r = MOTION_CMD_INVALID_PARAMS;
		}
		return r;
	case MOTCMD_SET_JOINT_BACKLASH:
	case MOTCMD_SET_JOINT_MIN_FERROR:
	case MOTCMD_SET_JOINT_MAX_FERROR:
		r = joint_ok(c, cfg, 0, msg, msglen);
		return r == MOTION_CMD_OK ? not_negative(c->value, "the value", msg, msglen) : r;
	case MOTCMD_SET_JOINT_VEL_LIMIT:
	case MOTCMD_SET_JOINT_ACC_LIMIT:
		r = joint_ok(c, cfg, 0, msg, msglen);
		return r == MOTION_CMD_OK ? positive(c->value, "the limit", msg, msglen) : r;
	case MOTCMD_SET_JOINT_COMP:
		return joint_ok(c, cfg, 0, msg, msglen);
	case MOTCMD_SET_AXIS_VEL_LIMIT:
	case MOTCMD_SET_AXIS_ACC_LIMIT:
		r = axis_ok(c, msg, msglen);
		return r == MOTION_CMD_OK ? positive(c->value, "the limit", msg, msglen) : r;
	case MOTCMD_SET_AXIS_EXT_OFFSET_LIMITS:
		r = axis_ok(c, msg, msglen);
		if (r == MOTION_CMD_OK)
			r = not_negative(c->vel, "the velocity", msg, msglen);
		return r == MOTION_CMD_OK ? not_negative(c->acc, "the acceleration", msg, msglen) : r;
	case MOTCMD_SET_AXIS_LOCKING_JOINT:
		r = axis_ok(c, msg, msglen);
		return r == MOTION_CMD_OK ? joint_ok(c, cfg, -1, msg, msglen) : r;
	case MOTCMD_SPINDLE_ON:
	case MOTCMD_SPINDLE_OFF:
	case MOTCMD_SPINDLE_ORIENT:
	case MOTCMD_SPINDLE_SCALE:
	case MOTCMD_SPINDLE_BRAKE_ENGAGE:
	case MOTCMD_SPINDLE_BRAKE_RELEASE:
	case MOTCMD_SPINDLE_INCREASE:
	case MOTCMD_SPINDLE_DECREASE:
		if (c->command == MOTCMD_SPINDLE_ORIENT && (c->mode < 0 || c->mode > 2))
			return bad(msg, msglen, "orient mode %d (0 shortest, 1 CW, 2 CCW)", c->mode, 0);
		return spindle_ok(c, cfg, true, msg, msglen);
	case MOTCMD_SET_SPINDLE_PARAMS:
		r = spindle_ok(c, cfg, false, msg, msglen);
		if (r == MOTION_CMD_OK && (c->spindle_params[0] < 0.0 || c->spindle_params[1] < c->spindle_params[0] ||
					   c->spindle_params[2] < 0.0 || c->spindle_params[3] < c->spindle_params[2] ||
					   c->spindle_params[4] < 0.0))
			r = bad(msg, msglen, "spindle speeds: need 0 <= min <= max and increment >= 0", 0, 0);
		return r;
	case MOTCMD_SET_DOUT:
		if (c->out < 0 || c->out >= cfg->num_dout)
			return bad(msg, msglen, "digital output %d out of range (0..%d)", c->out, cfg->num_dout - 1);
		return MOTION_CMD_OK;
	case MOTCMD_SET_AOUT:
		if (c->out < 0 || c->out >= cfg->num_aout)
			return bad(msg, msglen, "analog output %d out of range (0..%d)", c->out, cfg->num_aout - 1);
		return MOTION_CMD_OK;
	case MOTCMD_SET_LINE:
	case MOTCMD_SET_CIRCLE:
	case MOTCMD_PROBE:
	case MOTCMD_RIGID_TAP:
		r = positive(c->vel, "velocity", msg, msglen);
		if (r == MOTION_CMD_OK)
			r = positive(c->ini_maxvel, "maximum velocity", msg, msglen);
		if (r == MOTION_CMD_OK)
			r = positive(c->acc, "acceleration", msg, msglen);
		if (r == MOTION_CMD_OK && c->command == MOTCMD_SET_CIRCLE &&
		    c->normal[0] == 0.0 && c->normal[1] == 0.0 && c->normal[2] == 0.0)
			r = bad(msg, msglen, "arc normal vector is zero", 0, 0);
		if (r == MOTION_CMD_OK && c->command == MOTCMD_PROBE && (c->probe_type & ~3))
			r = bad(msg, msglen, "probe type %d (bits 0 and 1 only)", c->probe_type, 0);
		if (r == MOTION_CMD_OK && c->command == MOTCMD_RIGID_TAP)
			r = spindle_ok(c, cfg, false, msg, msglen);
		return r;
	case MOTCMD_SET_TERM_COND:
		if (c->termCond < MOTION_TERM_STOP || c->termCond > MOTION_TERM_PARABOLIC)
			return bad(msg, msglen, "term condition %d (0 stop, 1 exact, 2 blend)", c->termCond, 0);
		return not_negative(c->tolerance, "tolerance", msg, msglen);
	case MOTCMD_SET_VEL:
	case MOTCMD_SET_VEL_LIMIT:
	case MOTCMD_SET_ACC:
		return not_negative(c->vel + c->acc, "the value", msg, msglen) == MOTION_CMD_OK &&
		       c->vel >= 0.0 && c->acc >= 0.0 ? MOTION_CMD_OK :
		       bad(msg, msglen, "velocity and acceleration must not be negative", 0, 0);
	case MOTCMD_SET_NUM_JOINTS:
		if (c->count < 1 || c->count > cfg->num_joints)
			return bad(msg, msglen, "number of joints %d: motmod has %d", c->count, cfg->num_joints);
		return MOTION_CMD_OK;
	case MOTCMD_SET_MAX_FEED_OVERRIDE:
		return not_negative(c->scale, "maximum feed override", msg, msglen);
	default:
		return MOTION_CMD_OK;
	}
}
