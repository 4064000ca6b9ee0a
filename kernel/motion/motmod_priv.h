/* SPDX-License-Identifier: GPL-2.0-or-later */
/* motmod_priv.h - motmod's realtime state, shared by its translation units:
 *   motmod.c        load parameters, threads, pins + aliases, shared memory (no FP)
 *   motmod_init_fp.c  initial float values (called between rtapi_fpu_begin/end)
 *   command_fp.c    motion-command-handler: check and run one command
 *   control_fp.c    motion-controller: the per-period cycle (motion.md 3)
 *   joints_fp.c     per-joint parts of the cycle: inputs, faults, jogs, comp, outputs
 *   spindle_fp.c    spindle outputs (motion.md 14)
 *   error_fp.c      the error ring (motion_if.h)
 * Everything lives in one static struct motmod, set up at load: no allocation after.
 * Owner of every field: the servo thread (the two functions run in it, one after the
 * other), except what rtapi_app_main sets before hal_ready(). */
#ifndef MOTMOD_PRIV_H
#define MOTMOD_PRIV_H

#include "rtapi.h"
#include "hal.h"
#include "rtapi_string.h"
#include "motion_if.h"
#include "freetp.h"
#include "comp.h"
#include "../kins/kinematics.h"
#include "../kins/kins_bind.h"
#include "homing/homing.h"

struct mot_joint_pins {
	hal_float_t *motor_pos_cmd, *motor_pos_fb, *pos_cmd, *pos_fb, *coarse_pos_cmd;
	hal_float_t *vel_cmd, *acc_cmd, *motor_offset, *backlash_corr, *backlash_filt;
	hal_float_t *backlash_vel, *f_error, *f_error_lim, *free_pos_cmd, *free_vel_lim;
	hal_float_t *jog_scale, *jog_accel_fraction, *posthome_cmd, *motor_pos_probed;
	hal_bit_t *pos_lim_sw_in, *neg_lim_sw_in, *amp_enable_out, *amp_fault_in;
	hal_bit_t *jog_enable, *jog_vel_mode, *kb_jog_active, *wheel_jog_active;
	hal_bit_t *f_errored, *free_tp_enable, *in_position, *pos_hard_limit;
	hal_bit_t *neg_hard_limit, *active, *error, *faulted;
	hal_s32_t *jog_counts;
};

struct mot_axis_pins {
	hal_float_t *pos_cmd, *teleop_pos_cmd, *teleop_vel_cmd, *teleop_vel_lim;
	hal_float_t *jog_scale, *jog_accel_fraction, *eoffset_scale, *eoffset, *eoffset_request;
	hal_bit_t *teleop_tp_enable, *jog_enable, *jog_vel_mode, *kb_jog_active;
	hal_bit_t *wheel_jog_active, *eoffset_enable, *eoffset_clear;
	hal_s32_t *jog_counts, *eoffset_counts;
};

struct mot_spindle_pins {
	hal_bit_t *on, *forward, *reverse, *brake, *index_enable, *at_speed, *inhibit;
	hal_bit_t *amp_fault_in, *orient, *is_oriented, *locked;
	hal_float_t *speed_out, *speed_out_abs, *speed_out_rps, *speed_out_rps_abs;
	hal_float_t *speed_cmd_rps, *speed_in, *revs, *orient_angle;
	hal_s32_t *orient_mode, *orient_fault;
};

struct mot_pins {
	hal_bit_t *enable, *probe_input, *feed_hold, *feed_inhibit, *homing_inhibit;
	hal_bit_t *jog_inhibit, *jog_stop, *jog_stop_immediate;
	hal_float_t *adaptive_feed, *switchkins_type;
	hal_bit_t *motion_enabled, *in_position, *coord_mode, *teleop_mode, *coord_error;
	hal_bit_t *on_soft_limit, *is_all_homed, *jog_is_active, *tp_reverse;
	hal_bit_t *eoffset_active, *eoffset_limited;
	hal_s32_t *motion_type, *program_line;
	hal_float_t *current_vel, *requested_vel, *distance_to_go, *feed_upm;
	hal_float_t *feed_inches_per_minute, *feed_inches_per_second;
	hal_float_t *feed_mm_per_minute, *feed_mm_per_second;
	hal_float_t *tooloffset[MOTION_MAX_AXES];
	hal_u32_t *servo_last_period;
	hal_float_t *servo_last_period_ns;
	hal_bit_t *din[MOTION_MAX_DIO], *dout[MOTION_MAX_DIO];
	hal_float_t *ain[MOTION_MAX_AIO], *aout[MOTION_MAX_AIO];
	hal_bit_t *misc_error[MOTION_MAX_MISC_ERRORS];
	/* parameters (storage in HAL memory) */
	hal_bit_t debug_bit[2];
	hal_float_t debug_float[4];
	hal_s32_t debug_s32[2];
	/* planner debug parameters (motion.md 4.1): executing segment, first 4 queued */
	hal_float_t traj_pos_out, traj_vel_out;
	hal_u32_t traj_active_tc;
	hal_float_t tc_pos[4], tc_vel[4], tc_acc[4];
	hal_u32_t servo_overruns;
	struct mot_joint_pins joint[MOTION_MAX_JOINTS];
	struct mot_axis_pins axis[MOTION_MAX_AXES];
	struct mot_spindle_pins spindle[MOTION_MAX_SPINDLES];
};

struct mot_joint {
	bool active;		/* JOINT_ACTIVATE (all joints start active) */
	bool enabled;		/* JOINT_FLAG_ENABLE */
	bool error, fault, ferrored, on_pos_limit, on_neg_limit, inpos;
	bool limit_reported;	/* "on limit switch error" is said once */
	bool kb_jog_active, wheel_jog_active;
	bool jog_counts_init;
	bool was_on_limit;	/* for clearing the limit override after a jog */
	rtapi_s32 old_jog_counts;
	double pos_cmd, pos_fb, vel_cmd, acc_cmd, coarse_pos, motor_offset;
	double backlash, backlash_corr, backlash_filt, backlash_vel;
	double min_limit, max_limit, vel_limit, acc_limit;
	double min_ferror, max_ferror, ferror, ferror_limit, ferror_high_mark;
	double prev_pos_cmd, prev_vel_cmd;
	struct freetp free;
	struct comp_table comp;
};

struct mot_axis {
	bool kb_jog_active, wheel_jog_active, jog_counts_init;
	rtapi_s32 old_jog_counts;
	rtapi_s32 locking_joint;
	double min_limit, max_limit, vel_limit, acc_limit;
	struct freetp tp;
	/* external offset (eoffset_fp.c): eoff.curr_pos is the applied offset */
	struct freetp eoff;
	rtapi_s32 eoff_old_counts;
	double eoff_request;		/* counts x scale since TELEOP/COORD began */
	double eoff_vel, eoff_acc;	/* SET_AXIS_EXT_OFFSET_LIMITS; 0: none */
};

struct mot_spindle {
	double speed;		/* commanded rpm, signed */
	double scale;		/* override */
	double css_factor, xoffset;
	double min_fwd, max_fwd, min_rev, max_rev, increment;
	double orient_angle, speed_out, net_scale;
	rtapi_s32 state, direction, brake, locked, orient_state, orient_mode, orient_fault;
	bool fault_reported;
};

/* coordinated motion (COORD): the planner adaptor (coord_fp.c) */
struct mot_coord;

struct motmod {
	int comp_id;
	int shmem_id;
	int num_joints, num_extrajoints, num_spindles, num_misc_error;
	int num_din, num_dout, num_ain, num_aout;
	int rtapi_module_id;
	long traj_period_ns;
	struct motion_shmem *shm;
	struct mot_pins *pins;
	long servo_period_ns;
	double servo_period_s;
	struct kins_ops kins;		/* the loaded kinematics module (kins_bind.h) */
	KINEMATICS_TYPE kins_type;

	/* command handler */
	rtapi_u32 last_cmd_num;

	/* operating state (motion.md 6) */
	int state;			/* enum motion_state, derived each period */
	bool enabled, coord, teleop, error, inpos;
	bool enable_req, disable_req, free_req, teleop_req, coord_req;
	bool paused, stepping, on_soft_limit, soft_limit_reported;
	bool all_homed;
	bool teleop_after_homing;	/* Home-All done: TELEOP when homing is idle */
	rtapi_u32 override_mask;
	int enables_new;
	double feed_scale, rapid_scale, net_feed_scale, max_feed_scale;
	double net_rapid_scale, net_feed_scale_coord;	/* what the planner gets (COORD) */
	double spindle_tap_scale[MOTION_MAX_SPINDLES];	/* rigid tap reversal (planner) */
	double traj_vel, traj_acc, traj_vel_limit;
	int term_cond;
	double tolerance;

	/* world positions */
	EmcPose world_cmd, world_fb, world_home;
	bool world_fb_ok;
	KINEMATICS_FORWARD_FLAGS fflags;
	KINEMATICS_INVERSE_FLAGS iflags;
	double switchkins_prev;

	/* probing (motion.md 13) */
	bool probing, probe_tripped, probe_prev;
	bool eoffset_limited;		/* an external offset was clipped this period */
	bool probe_pos_pending;		/* a probe move ended without a trip: record once stopped */
	bool atspeed_next_feed;		/* SPINDLE_ON asked the next feed move to wait */
	int probe_type;
	bool no_probe_jog_error, no_probe_home_error;
	struct motion_pose probed;

	struct motion_pose tool_offset;
	rtapi_u8 dout_state[MOTION_MAX_DIO];
	double aout_value[MOTION_MAX_AIO];
	bool misc_reported[MOTION_MAX_MISC_ERRORS];
	bool enable_reported;
	long long last_clocks;

	struct mot_joint joint[MOTION_MAX_JOINTS];
	struct homing_joint hj[MOTION_MAX_JOINTS];
	struct mot_axis axis[MOTION_MAX_AXES];
	struct mot_spindle spindle[MOTION_MAX_SPINDLES];
	struct mot_coord *coord_tp;
};

/* error_fp.c: queue one message (printf format, no newline) in the error ring and log it */
void mot_error(struct motmod *m, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* homing's report function (homing_init) */
void mot_homing_report(const char *msg);
void mot_error_attach(struct motmod *m);

/* motmod_init_fp.c */
int mot_init_values(struct motmod *m);	/* 0 or -ENOMEM (planner memory) */
void mot_init_pin_values(struct motmod *m);

/* command_fp.c / control_fp.c: the two HAL functions (arg = struct motmod *) */
void mot_command_handler(void *arg, long period_ns);
void mot_controller(void *arg, long period_ns);

/* joints_fp.c */
void mot_process_joint_inputs(struct motmod *m);
void mot_check_joint_faults(struct motmod *m);
void mot_joint_jog_wheels(struct motmod *m, bool allowed);	/* allowed: FREE, no jog-inhibit */
void mot_axis_jog_wheels(struct motmod *m, bool allowed);	/* allowed: TELEOP, no jog-inhibit */
void mot_free_planners(struct motmod *m);

/* eoffset_fp.c: external offsets (after the operating mode, before the setpoints) */
void mot_eoffset_update(struct motmod *m);
void mot_eoffset_add(const struct motmod *m, EmcPose *world);	/* world += offsets */
bool mot_eoffset_moving(const struct motmod *m);
void mot_compensation(struct motmod *m);
void mot_joint_outputs(struct motmod *m);
bool mot_joint_jog_limits(struct motmod *m, int j, double *lo, double *hi);

/* spindle_fp.c */
void mot_spindle_inputs(struct motmod *m);
void mot_spindle_outputs(struct motmod *m);

/* control_fp.c helpers the command handler uses */
bool mot_all_homed(struct motmod *m);
void mot_set_free_from_cmd(struct motmod *m);
int mot_forward(struct motmod *m, const double *joints, EmcPose *world);
int mot_inverse(struct motmod *m, const EmcPose *world, double *joints);
int mot_world_to_joints(struct motmod *m, const EmcPose *world, double *joints);
void mot_pose_to_array(const EmcPose *p, double *v);
void mot_array_to_pose(const double *v, EmcPose *p);

#endif
