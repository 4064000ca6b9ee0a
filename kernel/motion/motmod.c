/* SPDX-License-Identifier: GPL-2.0-or-later */
/* motmod.c - the motion controller module, load side (no FP): module parameters
 * (motion.md 2) and their refusals, the kinematics-module check, threads
 * (init_threads rule), the shared-memory command/status block (motion_if.h), every
 * pin and parameter of motion.md 4 with the EMC2 names of motion.md 5 as aliases, the
 * homing pins (homing_init) and the two functions. The realtime work is in the *_fp.c
 * files (motmod_priv.h). A refusal prints one line and leaves nothing loaded. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "hal.h"
#include "motmod_priv.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("motion controller: free/teleop/coordinated motion, homing, HAL interface");

static int key = MOTION_DEFAULT_KEY;
RTAPI_MP_INT(key, "shared memory key of the command/status block (default 100)");
static long base_period_nsec = 0;
RTAPI_MP_LONG(base_period_nsec, "base thread period, ns (0: no base thread)");
static int base_thread_fp = 0;
RTAPI_MP_INT(base_thread_fp, "deprecated, ignored");
static long servo_period_nsec = 1000000;
RTAPI_MP_LONG(servo_period_nsec, "servo thread period, ns (default 1000000)");
static long traj_period_nsec = 0;
RTAPI_MP_LONG(traj_period_nsec, "trajectory period, ns (0: the servo period)");
static int num_joints = MOTION_MAX_JOINTS;
RTAPI_MP_INT(num_joints, "number of joints, 1..16 (default 16)");
static int num_extrajoints = 0;
RTAPI_MP_INT(num_extrajoints, "last joints homed but not used by kinematics, 0..num_joints");
static int num_spindles = 1;
RTAPI_MP_INT(num_spindles, "number of spindles, 0..8 (default 1)");
static int num_dio = -1;
RTAPI_MP_INT(num_dio, "number of digital inputs and outputs, 1..64 (default 4)");
static int num_aio = -1;
RTAPI_MP_INT(num_aio, "number of analog inputs and outputs, 1..64 (default 4)");
static char *names_din = 0;
RTAPI_MP_STRING(names_din, "names of the digital inputs (motion.din-NAME), comma separated");
static char *names_dout = 0;
RTAPI_MP_STRING(names_dout, "names of the digital outputs (motion.dout-NAME)");
static char *names_ain = 0;
RTAPI_MP_STRING(names_ain, "names of the analog inputs (motion.ain-NAME)");
static char *names_aout = 0;
RTAPI_MP_STRING(names_aout, "names of the analog outputs (motion.aout-NAME)");
static int num_misc_error = -1;
RTAPI_MP_INT(num_misc_error, "number of misc error inputs, 0..64 (default 0)");
static char *names_misc_errors = 0;
RTAPI_MP_STRING(names_misc_errors, "names of the misc error inputs (motion.err-NAME)");
static int unlock_joints_mask = 0;
RTAPI_MP_INT(unlock_joints_mask, "bit n: joint.n.unlock / is-unlocked pins (locking indexer)");

static struct motmod mot;	/* all of motmod's state (motmod_priv.h) */
static bool made_base_thread, made_servo_thread;	/* removed again when the load fails */

static const char axis_letters[MOTION_MAX_AXES] = { 'x', 'y', 'z', 'a', 'b', 'c', 'u', 'v', 'w' };

#define NAME_MAX_LEN 48		/* HAL names (RULINGS: at least 47 characters) */
#define NAMES_MAX 64

/* ---- pin helpers: one line each, errors propagate through err ---- */

static int pin(int err, hal_type_t type, hal_pin_dir_t dir, void *ptr, const char *name,
	       const char *alias)
{
	if (err)
		return err;
	err = hal_pin_new(name, type, dir, (void **)ptr, mot.comp_id);
	if (!err && alias)
		err = hal_pin_alias(name, alias);
	if (err)
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: cannot create pin %s%s%s (%d)\n", name,
				alias ? " alias " : "", alias ? alias : "", err);
	return err;
}

/* joint pin "joint.N.<suffix>", alias "axis.N.<emc2>" when emc2 is given */
static int jpin(int err, int n, hal_type_t type, hal_pin_dir_t dir, void *ptr, const char *suffix,
		const char *emc2)
{
	char name[NAME_MAX_LEN], alias[NAME_MAX_LEN];

	rtapi_snprintf(name, sizeof(name), "joint.%d.%s", n, suffix);
	if (emc2)
		rtapi_snprintf(alias, sizeof(alias), "axis.%d.%s", n, emc2);
	return pin(err, type, dir, ptr, name, emc2 ? alias : 0);
}

static int apin(int err, int l, hal_type_t type, hal_pin_dir_t dir, void *ptr, const char *suffix)
{
	char name[NAME_MAX_LEN];

	rtapi_snprintf(name, sizeof(name), "axis.%c.%s", axis_letters[l], suffix);
	return pin(err, type, dir, ptr, name, 0);
}

/* spindle pin "spindle.S.<suffix>"; spindle 0 also answers "motion.spindle-<emc2>" */
static int spin(int err, int s, hal_type_t type, hal_pin_dir_t dir, void *ptr, const char *suffix,
		const char *emc2)
{
	char name[NAME_MAX_LEN], alias[NAME_MAX_LEN];

	rtapi_snprintf(name, sizeof(name), "spindle.%d.%s", s, suffix);
	if (emc2 && s == 0)
		rtapi_snprintf(alias, sizeof(alias), "motion.spindle-%s", emc2);
	return pin(err, type, dir, ptr, name, emc2 && s == 0 ? alias : 0);
}

static int param(int err, hal_type_t type, hal_param_dir_t dir, volatile void *vptr, const char *name)
{
	void *ptr = (void *)vptr;	/* the HAL types are volatile */

	if (err)
		return err;
	switch (type) {
	case HAL_BIT:
		err = hal_param_bit_newf(dir, ptr, mot.comp_id, "%s", name);
		break;
	case HAL_FLOAT:
		err = hal_param_float_newf(dir, ptr, mot.comp_id, "%s", name);
		break;
	case HAL_S32:
		err = hal_param_s32_newf(dir, ptr, mot.comp_id, "%s", name);
		break;
	default:
		err = hal_param_u32_newf(dir, ptr, mot.comp_id, "%s", name);
		break;
	}
	if (err)
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: cannot create parameter %s (%d)\n", name, err);
	return err;
}

/* ---- module parameters ---- */

/* Split a comma list into names[] (pointers into buf); blanks around names ignored.
 * Returns the count, or -EINVAL after a message (empty or too long name, too many). */
static int split_names(const char *what, const char *list, char *buf, int buflen,
		       const char **names, int max)
{
	int n = 0;
	char *p, *start;

	if (rtapi_strlcpy(buf, list, buflen) >= (size_t)buflen) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: %s='%s' is too long\n", what, list);
		return -EINVAL;
	}
	for (p = buf; *p;) {
		char *end;

		while (*p == ' ')
			p++;
		start = p;
		while (*p && *p != ',')
			p++;
		end = p;
		if (*p)
			*p++ = 0;
		while (end > start && end[-1] == ' ')
			*--end = 0;
		if (!*start || n >= max || strlen(start) > 30) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"motmod: %s='%s': %s\n", what, list,
					!*start ? "empty name" : n >= max ? "too many names" :
					"a name is longer than 30 characters");
			return -EINVAL;
		}
		names[n++] = start;
	}
	if (!n) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: %s is empty\n", what);
		return -EINVAL;
	}
	return n;
}

static char din_buf[512], dout_buf[512], ain_buf[512], aout_buf[512], misc_buf[1024];
static const char *din_names[NAMES_MAX], *dout_names[NAMES_MAX], *ain_names[NAMES_MAX],
	*aout_names[NAMES_MAX], *misc_names[NAMES_MAX];

/* The count of one I/O kind: from names (when given) or the number parameter. */
static int io_count(const char *num_what, int num, int num_min, int num_default, const char *what,
		    const char *names, char *buf, int buflen, const char **out, const char *kind)
{
	if (names && *names) {
		if (num >= 0) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"motmod: Can't specify both names and number for %s (%s and %s)\n",
					kind, what, num_what);
			return -EINVAL;
		}
		return split_names(what, names, buf, buflen, out, NAMES_MAX);
	}
	if (num < 0)
		return num_default;
	if (num < num_min || num > NAMES_MAX) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: %s=%d out of range, must be %d..%d\n",
				num_what, num, num_min, NAMES_MAX);
		return -EINVAL;
	}
	return num;
}

static int check_params(void)
{
	if (num_joints < 1 || num_joints > MOTION_MAX_JOINTS) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: num_joints=%d out of range, must be 1..%d\n",
				num_joints, MOTION_MAX_JOINTS);
		return -EINVAL;
	}
	if (num_extrajoints < 0 || num_extrajoints > num_joints) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: num_extrajoints=%d out of range, must be 0..num_joints (%d)\n",
				num_extrajoints, num_joints);
		return -EINVAL;
	}
	if (num_spindles < 0 || num_spindles > MOTION_MAX_SPINDLES) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: num_spindles=%d out of range, must be 0..%d\n",
				num_spindles, MOTION_MAX_SPINDLES);
		return -EINVAL;
	}
	if (servo_period_nsec <= 0 || base_period_nsec < 0 || traj_period_nsec < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: periods must not be negative and servo_period_nsec must be > 0 (base %ld, servo %ld, traj %ld)\n",
				base_period_nsec, servo_period_nsec, traj_period_nsec);
		return -EINVAL;
	}
	if (unlock_joints_mask < 0 || (unlock_joints_mask >> num_joints)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: unlock_joints_mask=0x%x names joints beyond num_joints=%d\n",
				unlock_joints_mask, num_joints);
		return -EINVAL;
	}
	mot.num_din = io_count("num_dio", num_dio, 1, 4, "names_din", names_din, din_buf,
			       sizeof(din_buf), din_names, "digital inputs");
	if (mot.num_din < 0)
		return mot.num_din;
	mot.num_dout = io_count("num_dio", num_dio, 1, 4, "names_dout", names_dout, dout_buf,
				sizeof(dout_buf), dout_names, "digital outputs");
	if (mot.num_dout < 0)
		return mot.num_dout;
	mot.num_ain = io_count("num_aio", num_aio, 1, 4, "names_ain", names_ain, ain_buf,
			       sizeof(ain_buf), ain_names, "analog inputs");
	if (mot.num_ain < 0)
		return mot.num_ain;
	mot.num_aout = io_count("num_aio", num_aio, 1, 4, "names_aout", names_aout, aout_buf,
				sizeof(aout_buf), aout_names, "analog outputs");
	if (mot.num_aout < 0)
		return mot.num_aout;
	mot.num_misc_error = io_count("num_misc_error", num_misc_error, 0, 0, "names_misc_errors",
				      names_misc_errors, misc_buf, sizeof(misc_buf), misc_names,
				      "misc errors");
	if (mot.num_misc_error < 0)
		return mot.num_misc_error;
	mot.num_joints = num_joints;
	mot.num_extrajoints = num_extrajoints;
	mot.num_spindles = num_spindles;
	return 0;
}

/* init_threads (motion.md 2): base 0 -> servo; traj 0 -> servo; servo < base refused;
 * servo rounded to a whole multiple of base; base-thread only when that is > 1. */
static int make_threads(void)
{
	long base = base_period_nsec ? base_period_nsec : servo_period_nsec;
	long servo = servo_period_nsec, ratio;
	int err;

	if (servo < base) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: bad servo period: servo_period_nsec=%ld is shorter than base_period_nsec=%ld\n",
				servo, base);
		return -EINVAL;
	}
	ratio = (servo + base / 2) / base;
	servo = base * ratio;
	if (ratio > 1) {
		err = hal_create_thread("base-thread", base, 0);
		if (err) {
			rtapi_print_msg(RTAPI_MSG_ERR, "motmod: cannot create base-thread (%d)\n", err);
			return err;
		}
		made_base_thread = true;
	}
	err = hal_create_thread("servo-thread", servo, 1);
	if (err) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: cannot create servo-thread (%d)\n", err);
		return err;
	}
	made_servo_thread = true;
	mot.servo_period_ns = servo;
	mot.traj_period_ns = traj_period_nsec ? traj_period_nsec : servo;
	return 0;
}

/* ---- pins ---- */

static int export_joint(int err, int n)
{
	struct mot_joint_pins *p = &mot.pins->joint[n];

	err = jpin(err, n, HAL_FLOAT, HAL_OUT, &p->motor_pos_cmd, "motor-pos-cmd", "motor-pos-cmd");
	err = jpin(err, n, HAL_FLOAT, HAL_IN, &p->motor_pos_fb, "motor-pos-fb", "motor-pos-fb");
	err = jpin(err, n, HAL_FLOAT, HAL_OUT, &p->pos_cmd, "pos-cmd", "joint-pos-cmd");
	err = jpin(err, n, HAL_FLOAT, HAL_OUT, &p->pos_fb, "pos-fb", "joint-pos-fb");
	err = jpin(err, n, HAL_FLOAT, HAL_OUT, &p->coarse_pos_cmd, "coarse-pos-cmd", "coarse-pos-cmd");
	err = jpin(err, n, HAL_FLOAT, HAL_OUT, &p->vel_cmd, "vel-cmd", "joint-vel-cmd");
	err = jpin(err, n, HAL_FLOAT, HAL_OUT, &p->acc_cmd, "acc-cmd", 0);
	err = jpin(err, n, HAL_FLOAT, HAL_OUT, &p->motor_offset, "motor-offset", "motor-offset");
	err = jpin(err, n, HAL_BIT, HAL_IN, &p->pos_lim_sw_in, "pos-lim-sw-in", "pos-lim-sw-in");
	err = jpin(err, n, HAL_BIT, HAL_IN, &p->neg_lim_sw_in, "neg-lim-sw-in", "neg-lim-sw-in");
	err = jpin(err, n, HAL_BIT, HAL_OUT, &p->amp_enable_out, "amp-enable-out", "amp-enable-out");
	err = jpin(err, n, HAL_BIT, HAL_IN, &p->amp_fault_in, "amp-fault-in", "amp-fault-in");
	err = jpin(err, n, HAL_S32, HAL_IN, &p->jog_counts, "jog-counts", "jog-counts");
	err = jpin(err, n, HAL_BIT, HAL_IN, &p->jog_enable, "jog-enable", "jog-enable");
	err = jpin(err, n, HAL_FLOAT, HAL_IN, &p->jog_scale, "jog-scale", "jog-scale");
	err = jpin(err, n, HAL_BIT, HAL_IN, &p->jog_vel_mode, "jog-vel-mode", "jog-vel-mode");
	err = jpin(err, n, HAL_FLOAT, HAL_IN, &p->jog_accel_fraction, "jog-accel-fraction", 0);
	err = jpin(err, n, HAL_BIT, HAL_OUT, &p->kb_jog_active, "kb-jog-active", "kb-jog-active");
	err = jpin(err, n, HAL_BIT, HAL_OUT, &p->wheel_jog_active, "wheel-jog-active", "wheel-jog-active");
	err = jpin(err, n, HAL_FLOAT, HAL_OUT, &p->backlash_corr, "backlash-corr", "backlash-corr");
	err = jpin(err, n, HAL_FLOAT, HAL_OUT, &p->backlash_filt, "backlash-filt", "backlash-filt");
	err = jpin(err, n, HAL_FLOAT, HAL_OUT, &p->backlash_vel, "backlash-vel", "backlash-vel");
	err = jpin(err, n, HAL_FLOAT, HAL_OUT, &p->f_error, "f-error", "f-error");
	err = jpin(err, n, HAL_FLOAT, HAL_OUT, &p->f_error_lim, "f-error-lim", "f-error-lim");
	err = jpin(err, n, HAL_BIT, HAL_OUT, &p->f_errored, "f-errored", "f-errored");
	err = jpin(err, n, HAL_FLOAT, HAL_OUT, &p->free_pos_cmd, "free-pos-cmd", "free-pos-cmd");
	err = jpin(err, n, HAL_FLOAT, HAL_OUT, &p->free_vel_lim, "free-vel-lim", "free-vel-lim");
	err = jpin(err, n, HAL_BIT, HAL_OUT, &p->free_tp_enable, "free-tp-enable", "free-tp-enable");
	err = jpin(err, n, HAL_BIT, HAL_OUT, &p->in_position, "in-position", "in-position");
	err = jpin(err, n, HAL_BIT, HAL_OUT, &p->pos_hard_limit, "pos-hard-limit", "pos-hard-limit");
	err = jpin(err, n, HAL_BIT, HAL_OUT, &p->neg_hard_limit, "neg-hard-limit", "neg-hard-limit");
	err = jpin(err, n, HAL_BIT, HAL_OUT, &p->active, "active", "active");
	err = jpin(err, n, HAL_BIT, HAL_OUT, &p->error, "error", "error");
	err = jpin(err, n, HAL_BIT, HAL_OUT, &p->faulted, "faulted", "faulted");
	/* seed motion(9) lists axis.N.motor-pos-probed (EMC2 never created it): accepted
	 * under both names so EMC2-era files that net it load; motion does not read it */
	err = jpin(err, n, HAL_FLOAT, HAL_IN, &p->motor_pos_probed, "motor-pos-probed", "motor-pos-probed");
	if (n >= mot.num_joints - mot.num_extrajoints)
		err = jpin(err, n, HAL_FLOAT, HAL_IN, &p->posthome_cmd, "posthome-cmd", 0);
	return err;
}

static int export_axis(int err, int l)
{
	struct mot_axis_pins *p = &mot.pins->axis[l];

	err = apin(err, l, HAL_FLOAT, HAL_OUT, &p->pos_cmd, "pos-cmd");
	err = apin(err, l, HAL_FLOAT, HAL_OUT, &p->teleop_pos_cmd, "teleop-pos-cmd");
	err = apin(err, l, HAL_FLOAT, HAL_OUT, &p->teleop_vel_cmd, "teleop-vel-cmd");
	err = apin(err, l, HAL_FLOAT, HAL_OUT, &p->teleop_vel_lim, "teleop-vel-lim");
	err = apin(err, l, HAL_BIT, HAL_OUT, &p->teleop_tp_enable, "teleop-tp-enable");
	err = apin(err, l, HAL_S32, HAL_IN, &p->jog_counts, "jog-counts");
	err = apin(err, l, HAL_BIT, HAL_IN, &p->jog_enable, "jog-enable");
	err = apin(err, l, HAL_FLOAT, HAL_IN, &p->jog_scale, "jog-scale");
	err = apin(err, l, HAL_BIT, HAL_IN, &p->jog_vel_mode, "jog-vel-mode");
	err = apin(err, l, HAL_FLOAT, HAL_IN, &p->jog_accel_fraction, "jog-accel-fraction");
	err = apin(err, l, HAL_BIT, HAL_OUT, &p->kb_jog_active, "kb-jog-active");
	err = apin(err, l, HAL_BIT, HAL_OUT, &p->wheel_jog_active, "wheel-jog-active");
	err = apin(err, l, HAL_BIT, HAL_IN, &p->eoffset_enable, "eoffset-enable");
	err = apin(err, l, HAL_BIT, HAL_IN, &p->eoffset_clear, "eoffset-clear");
	err = apin(err, l, HAL_S32, HAL_IN, &p->eoffset_counts, "eoffset-counts");
	err = apin(err, l, HAL_FLOAT, HAL_IN, &p->eoffset_scale, "eoffset-scale");
	err = apin(err, l, HAL_FLOAT, HAL_OUT, &p->eoffset, "eoffset");
	err = apin(err, l, HAL_FLOAT, HAL_OUT, &p->eoffset_request, "eoffset-request");
	return err;
}

static int export_spindle(int err, int s)
{
	struct mot_spindle_pins *p = &mot.pins->spindle[s];

	err = spin(err, s, HAL_BIT, HAL_OUT, &p->on, "on", "on");
	err = spin(err, s, HAL_BIT, HAL_OUT, &p->forward, "forward", "forward");
	err = spin(err, s, HAL_BIT, HAL_OUT, &p->reverse, "reverse", "reverse");
	err = spin(err, s, HAL_BIT, HAL_OUT, &p->brake, "brake", "brake");
	err = spin(err, s, HAL_FLOAT, HAL_OUT, &p->speed_out, "speed-out", "speed-out");
	err = spin(err, s, HAL_FLOAT, HAL_OUT, &p->speed_out_abs, "speed-out-abs", 0);
	err = spin(err, s, HAL_FLOAT, HAL_OUT, &p->speed_out_rps, "speed-out-rps", "speed-out-rps");
	err = spin(err, s, HAL_FLOAT, HAL_OUT, &p->speed_out_rps_abs, "speed-out-rps-abs", 0);
	err = spin(err, s, HAL_FLOAT, HAL_OUT, &p->speed_cmd_rps, "speed-cmd-rps", "speed-cmd-rps");
	err = spin(err, s, HAL_FLOAT, HAL_IN, &p->speed_in, "speed-in", "speed-in");
	err = spin(err, s, HAL_FLOAT, HAL_IN, &p->revs, "revs", "revs");
	err = spin(err, s, HAL_BIT, HAL_IO, &p->index_enable, "index-enable", "index-enable");
	err = spin(err, s, HAL_BIT, HAL_IN, &p->at_speed, "at-speed", "at-speed");
	err = spin(err, s, HAL_BIT, HAL_IN, &p->inhibit, "inhibit", 0);
	err = spin(err, s, HAL_BIT, HAL_IN, &p->amp_fault_in, "amp-fault-in", 0);
	err = spin(err, s, HAL_BIT, HAL_OUT, &p->orient, "orient", "orient");
	err = spin(err, s, HAL_FLOAT, HAL_OUT, &p->orient_angle, "orient-angle", "orient-angle");
	err = spin(err, s, HAL_S32, HAL_OUT, &p->orient_mode, "orient-mode", "orient-mode");
	err = spin(err, s, HAL_BIT, HAL_IN, &p->is_oriented, "is-oriented", "is-oriented");
	err = spin(err, s, HAL_S32, HAL_IN, &p->orient_fault, "orient-fault", "orient-fault");
	err = spin(err, s, HAL_BIT, HAL_OUT, &p->locked, "locked", "locked");
	if (!err && s == 0)	/* the seed's spelling too (RULINGS: misspelt names kept) */
		err = hal_pin_alias("spindle.0.locked", "motion.pindle-locked");
	return err;
}

/* numbered ("motion.digital-in-00") or named ("motion.din-NAME") I/O pins */
static int io_pins(int err, int count, const char **names, hal_type_t type, hal_pin_dir_t dir,
		   void **ptrs, const char *numbered, const char *named)
{
	char name[NAME_MAX_LEN];
	int i;

	for (i = 0; !err && i < count; i++) {
		if (names)
			rtapi_snprintf(name, sizeof(name), "motion.%s-%s", named, names[i]);
		else
			rtapi_snprintf(name, sizeof(name), "motion.%s-%02d", numbered, i);
		err = pin(err, type, dir, &ptrs[i], name, 0);
	}
	return err;
}

static int export_motion(int err)
{
	struct mot_pins *p = mot.pins;
	char name[NAME_MAX_LEN];
	int l, t;

	err = pin(err, HAL_BIT, HAL_IN, &p->enable, "motion.enable", 0);
	err = pin(err, HAL_BIT, HAL_IN, &p->probe_input, "motion.probe-input", 0);
	err = pin(err, HAL_FLOAT, HAL_IN, &p->adaptive_feed, "motion.adaptive-feed", 0);
	err = pin(err, HAL_BIT, HAL_IN, &p->feed_hold, "motion.feed-hold", 0);
	err = pin(err, HAL_BIT, HAL_IN, &p->feed_inhibit, "motion.feed-inhibit", 0);
	err = pin(err, HAL_BIT, HAL_IN, &p->homing_inhibit, "motion.homing-inhibit", 0);
	err = pin(err, HAL_BIT, HAL_IN, &p->jog_inhibit, "motion.jog-inhibit", 0);
	err = pin(err, HAL_BIT, HAL_IN, &p->jog_stop, "motion.jog-stop", 0);
	err = pin(err, HAL_BIT, HAL_IN, &p->jog_stop_immediate, "motion.jog-stop-immediate", 0);
	err = pin(err, HAL_FLOAT, HAL_IN, &p->switchkins_type, "motion.switchkins-type", 0);
	err = pin(err, HAL_BIT, HAL_OUT, &p->motion_enabled, "motion.motion-enabled", 0);
	/* seed: motion.motion-inpos (EMC2 commented its creation out): an alias */
	err = pin(err, HAL_BIT, HAL_OUT, &p->in_position, "motion.in-position", "motion.motion-inpos");
	err = pin(err, HAL_BIT, HAL_OUT, &p->coord_mode, "motion.coord-mode", 0);
	err = pin(err, HAL_BIT, HAL_OUT, &p->teleop_mode, "motion.teleop-mode", 0);
	err = pin(err, HAL_BIT, HAL_OUT, &p->coord_error, "motion.coord-error", 0);
	err = pin(err, HAL_BIT, HAL_OUT, &p->on_soft_limit, "motion.on-soft-limit", 0);
	err = pin(err, HAL_BIT, HAL_OUT, &p->is_all_homed, "motion.is-all-homed", 0);
	err = pin(err, HAL_S32, HAL_OUT, &p->motion_type, "motion.motion-type", 0);
	err = pin(err, HAL_S32, HAL_OUT, &p->program_line, "motion.program-line", 0);
	err = pin(err, HAL_FLOAT, HAL_OUT, &p->current_vel, "motion.current-vel", 0);
	err = pin(err, HAL_FLOAT, HAL_OUT, &p->requested_vel, "motion.requested-vel", 0);
	err = pin(err, HAL_FLOAT, HAL_OUT, &p->distance_to_go, "motion.distance-to-go", 0);
	err = pin(err, HAL_FLOAT, HAL_OUT, &p->feed_upm, "motion.feed-upm", 0);
	err = pin(err, HAL_FLOAT, HAL_OUT, &p->feed_inches_per_minute, "motion.feed-inches-per-minute", 0);
	err = pin(err, HAL_FLOAT, HAL_OUT, &p->feed_inches_per_second, "motion.feed-inches-per-second", 0);
	err = pin(err, HAL_FLOAT, HAL_OUT, &p->feed_mm_per_minute, "motion.feed-mm-per-minute", 0);
	err = pin(err, HAL_FLOAT, HAL_OUT, &p->feed_mm_per_second, "motion.feed-mm-per-second", 0);
	err = pin(err, HAL_BIT, HAL_OUT, &p->jog_is_active, "motion.jog-is-active", 0);
	err = pin(err, HAL_BIT, HAL_OUT, &p->tp_reverse, "motion.tp-reverse", 0);
	err = pin(err, HAL_BIT, HAL_OUT, &p->eoffset_active, "motion.eoffset-active", 0);
	err = pin(err, HAL_BIT, HAL_OUT, &p->eoffset_limited, "motion.eoffset-limited", 0);
	err = pin(err, HAL_U32, HAL_OUT, &p->servo_last_period, "motion.servo.last-period", 0);
	err = pin(err, HAL_FLOAT, HAL_OUT, &p->servo_last_period_ns, "motion.servo.last-period-ns", 0);
	for (l = 0; !err && l < MOTION_MAX_AXES; l++) {
		rtapi_snprintf(name, sizeof(name), "motion.tooloffset.%c", axis_letters[l]);
		err = pin(err, HAL_FLOAT, HAL_OUT, &p->tooloffset[l], name, 0);
	}
	err = io_pins(err, mot.num_din, names_din && *names_din ? din_names : 0, HAL_BIT, HAL_IN,
		      (void **)p->din, "digital-in", "din");
	err = io_pins(err, mot.num_dout, names_dout && *names_dout ? dout_names : 0, HAL_BIT,
		      HAL_OUT, (void **)p->dout, "digital-out", "dout");
	err = io_pins(err, mot.num_ain, names_ain && *names_ain ? ain_names : 0, HAL_FLOAT, HAL_IN,
		      (void **)p->ain, "analog-in", "ain");
	err = io_pins(err, mot.num_aout, names_aout && *names_aout ? aout_names : 0, HAL_FLOAT,
		      HAL_OUT, (void **)p->aout, "analog-out", "aout");
	err = io_pins(err, mot.num_misc_error,
		      names_misc_errors && *names_misc_errors ? misc_names : 0, HAL_BIT, HAL_IN,
		      (void **)p->misc_error, "misc-error", "err");
	err = param(err, HAL_BIT, HAL_RO, &p->debug_bit[0], "motion.debug-bit-0");
	err = param(err, HAL_BIT, HAL_RO, &p->debug_bit[1], "motion.debug-bit-1");
	err = param(err, HAL_FLOAT, HAL_RO, &p->debug_float[0], "motion.debug-float-0");
	err = param(err, HAL_FLOAT, HAL_RO, &p->debug_float[1], "motion.debug-float-1");
	err = param(err, HAL_FLOAT, HAL_RO, &p->debug_float[2], "motion.debug-float-2");
	err = param(err, HAL_FLOAT, HAL_RO, &p->debug_float[3], "motion.debug-float-3");
	err = param(err, HAL_S32, HAL_RO, &p->debug_s32[0], "motion.debug-s32-0");
	err = param(err, HAL_S32, HAL_RO, &p->debug_s32[1], "motion.debug-s32-1");
	err = param(err, HAL_FLOAT, HAL_RO, &p->traj_pos_out, "traj.pos_out");
	err = param(err, HAL_FLOAT, HAL_RO, &p->traj_vel_out, "traj.vel_out");
	err = param(err, HAL_U32, HAL_RO, &p->traj_active_tc, "traj.active_tc");
	for (t = 0; t < 4; t++) {
		rtapi_snprintf(name, sizeof(name), "tc.%d.pos", t);
		err = param(err, HAL_FLOAT, HAL_RO, &p->tc_pos[t], name);
		rtapi_snprintf(name, sizeof(name), "tc.%d.vel", t);
		err = param(err, HAL_FLOAT, HAL_RO, &p->tc_vel[t], name);
		rtapi_snprintf(name, sizeof(name), "tc.%d.acc", t);
		err = param(err, HAL_FLOAT, HAL_RO, &p->tc_acc[t], name);
	}
	/* seed's motion.servo.overruns (removed in 2.9): periods over 1.5 nominal */
	err = param(err, HAL_U32, HAL_RO, &p->servo_overruns, "motion.servo.overruns");
	return err;
}

static int export_all(void)
{
	int err = 0, i;

	err = export_motion(err);
	for (i = 0; i < mot.num_joints; i++)
		err = export_joint(err, i);
	for (i = 0; i < MOTION_MAX_AXES; i++)
		err = export_axis(err, i);
	for (i = 0; i < mot.num_spindles; i++)
		err = export_spindle(err, i);
	return err;
}

/* ---- shared memory ---- */

static int make_shmem(void)
{
	void *p;
	int err;

	mot.rtapi_module_id = rtapi_init("motmod");
	if (mot.rtapi_module_id < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: rtapi_init failed (%d)\n", mot.rtapi_module_id);
		return mot.rtapi_module_id;
	}
	mot.shmem_id = rtapi_shmem_new(key, mot.rtapi_module_id, sizeof(struct motion_shmem));
	if (mot.shmem_id < 0) {
		err = mot.shmem_id;
		mot.shmem_id = 0;
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: cannot create shared memory key=%d (%d)\n", key, err);
		return err;
	}
	err = rtapi_shmem_getptr(mot.shmem_id, &p);
	if (err) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: cannot map shared memory key=%d (%d)\n", key, err);
		return err;
	}
	mot.shm = p;
	if (mot.shm->hdr.magic == MOTION_IF_MAGIC) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: shared memory key=%d is in use by another motmod\n", key);
		mot.shm = 0;
		return -EBUSY;
	}
	memset(mot.shm, 0, sizeof(*mot.shm));
	return 0;
}

/* a failed load: everything, threads included */
static void remove_all(void)
{
	if (mot.comp_id > 0)
		hal_exit(mot.comp_id);
	if (made_servo_thread)
		hal_thread_delete("servo-thread");
	if (made_base_thread)
		hal_thread_delete("base-thread");
	made_servo_thread = made_base_thread = false;
	if (mot.shm)
		mot.shm->hdr.magic = 0;
	if (mot.shmem_id > 0)
		rtapi_shmem_delete(mot.shmem_id, mot.rtapi_module_id);
	if (mot.rtapi_module_id > 0)
		rtapi_exit(mot.rtapi_module_id);
	mot.comp_id = mot.shmem_id = mot.rtapi_module_id = 0;
	mot.shm = 0;
	kins_unbind(&mot.kins);	/* after hal_exit: no thread runs motion any more */
}

int rtapi_app_main(void)
{
	int err, i;

	memset(&mot, 0, sizeof(mot));
	err = check_params();
	if (err)
		return err;
	if (kins_bind(&mot.kins)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: no kinematics module is loaded: load one first (e.g. 'loadrt trivkins')\n");
		return -ENOENT;
	}
	mot.kins_type = mot.kins.type();
	if (mot.num_extrajoints > 0 && mot.kins_type != KINEMATICS_BOTH) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: num_extrajoints=%d needs kinematics of type BOTH (kinstype=both)\n",
				mot.num_extrajoints);
		kins_unbind(&mot.kins);
		return -EINVAL;
	}
	mot.comp_id = hal_init("motmod");
	if (mot.comp_id < 0)
		return mot.comp_id;
	err = make_threads();
	if (!err)
		err = make_shmem();
	if (!err) {
		mot.pins = hal_malloc(sizeof(*mot.pins));
		if (!mot.pins) {
			rtapi_print_msg(RTAPI_MSG_ERR, "motmod: out of HAL memory\n");
			err = -ENOMEM;
		}
	}
	if (!err)
		err = export_all();
	if (!err) {
		err = homing_init(mot.comp_id, mot.num_joints, mot.num_extrajoints,
				  (rtapi_u32)unlock_joints_mask, mot.hj, mot_homing_report);
		if (err)
			rtapi_print_msg(RTAPI_MSG_ERR, "motmod: homing_init failed (%d)\n", err);
	}
	if (!err)
		err = hal_export_funct("motion-command-handler", mot_command_handler, &mot, 1, 0,
				       mot.comp_id);
	if (!err)
		err = hal_export_funct("motion-controller", mot_controller, &mot, 1, 0, mot.comp_id);
	if (err) {
		remove_all();
		return err;
	}
	for (i = 0; i < mot.num_joints; i++)
		mot.joint[i].active = true;
	rtapi_fpu_begin();
	err = mot_init_values(&mot);
	if (!err)
		mot_init_pin_values(&mot);
	rtapi_fpu_end();
	if (err) {
		rtapi_print_msg(RTAPI_MSG_ERR, "motmod: no memory for the trajectory planner\n");
		remove_all();
		return err;
	}
	mot.shm->hdr.version = MOTION_IF_VERSION;
	mot.shm->hdr.size = sizeof(struct motion_shmem);
	/* published last: a client that sees the magic sees a set-up block */
	__atomic_store_n(&mot.shm->hdr.magic, MOTION_IF_MAGIC, __ATOMIC_RELEASE);
	hal_ready(mot.comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	/* the threads stay, as LinuxCNC's motmod leaves them (other functions may use them) */
	made_servo_thread = made_base_thread = false;
	remove_all();
}
