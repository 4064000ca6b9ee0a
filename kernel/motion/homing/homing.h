/* SPDX-License-Identifier: GPL-2.0-or-later */
/* homing.h - the homing part of motmod: the per-joint homing state machine with every
 * HOME_* option, Home-All and home sequences (motion.md section 9), and the homing HAL
 * pins. The function set is LinuxCNC 2.9's homing-module interface (motion.md 9.8);
 * here the code is linked into motmod itself (no separate homemod module).
 *
 * Module sources (motmod's modules.manifest line lists all three):
 *   motion/homing/homing_core.c  setup, getters, no FP, no HAL
 *   motion/homing/homing_pins.c  homing_init (HAL pins and their aliases), pin copy, no FP
 *   motion/homing/homing_fp.c    the state machine and everything that touches a double
 * Every function taking or returning a double, and do_homing(), is in homing_fp.c:
 * call them only from FP code (motmod's realtime functions, uses_fp = 1, or init code
 * between rtapi_fpu_begin() and rtapi_fpu_end()).
 *
 * HAL pins homing_init() creates (motion.md 4.3), N = joint number, with the EMC2
 * name (motion.md 5) of the same pin as an alias:
 *   joint.N.home-sw-in     IN  bit   alias axis.N.home-sw-in
 *   joint.N.index-enable   IO  bit   alias axis.N.index-enable
 *   joint.N.homing         OUT bit   alias axis.N.homing
 *   joint.N.homed          OUT bit   alias axis.N.homed
 *   joint.N.home-state     OUT s32   alias axis.N.home-state  (state numbers below)
 *   joint.N.unlock         OUT bit   alias axis.N.unlock       only joints in
 *   joint.N.is-unlocked    IN  bit   alias axis.N.is-unlocked  unlock_joints_mask
 * motmod creates every other joint.N.* pin (and its alias) and must not create these.
 *
 * What motmod calls, when (all in the servo thread unless stated):
 *   rtapi_app_main:   homing_init() once, after hal_init(), before hal_ready().
 *   command handler:  set_joint_homing_params() / update_joint_homing_params() on
 *                     SET_JOINT_HOMING_PARAMS / UPDATE_JOINT_HOMING_PARAMS;
 *                     JOINT_HOME: motmod checks FREE ("must be in joint mode to home"),
 *                     motion.homing-inhibit ("Homing denied by motion.homing-inhibit
 *                     joint=N") and enabled, then do_home_joint(joint) (-1 = all);
 *                     JOINT_UNHOME: motmod checks FREE or DISABLED, then
 *                     do_unhome_joint(joint) (-1 all, -2 volatile only);
 *                     ABORT (not TELEOP/COORD) and DISABLE/ENABLE: do_cancel_homing(-1);
 *                     jogs: refuse while get_homing_is_active() ("Can't jog any joints
 *                     while homing."), joint jogs of joints with
 *                     get_home_is_synchronized() && !get_homed() refused, jogs/wheel of
 *                     get_home_needs_unlock_first() joints refused.
 *   motion-controller, in this order each period:
 *     1. read_homing_in_pins()                       (motion.md 3, step 2)
 *     2. process_inputs: pos_fb of joint j as usual, except in the period in which
 *        get_homing_at_index_search_wait(j) && !get_index_enable(j): pos_fb := pos_cmd
 *        (hides the encoder's jump at the index). Limit switch faults are not raised
 *        for a joint while get_homing(j) (homing handles them itself).
 *     3. probe: a rising edge of motion.probe-input while idle in coordinated sense and
 *        get_homing_is_active(): homing_probe_trip(no_probe_home_error).
 *     4. fault check / set_operating_mode: on any disable, do_cancel_homing(-1).
 *     5. only in FREE state: fill struct homing_joint of every joint (fields marked
 *        "motmod ->"), call do_homing(period_ns), copy back the fields marked
 *        "homing ->" and "both" (all of them, every joint, homing or not: see the
 *        struct); if do_homing() returned true, request TELEOP.
 *        (motmod may also keep struct homing_joint as its own storage of these values.)
 *     6. the free planner runs with free_pos_cmd / free_vel_lim / free_tp_enable as
 *        homing left them (homing owns them while get_homing(j)).
 *     7. write_homing_out_pins()                     (motion.md 3, step 15)
 * Errors (the texts of motion.md 9) are given to the report function of homing_init(),
 * one formatted line each, from realtime context (motmod puts them in its error ring). */
#ifndef HOMING_H
#define HOMING_H

#include "rtapi.h"

#ifdef __cplusplus
extern "C" {
#endif

#define HOMING_MAX_JOINTS 16	/* EMCMOT_MAX_JOINTS */

/* Flag bits of SET_JOINT_HOMING_PARAMS (2.9 values, motion.md 9.1). */
#define HOME_IGNORE_LIMITS		1
#define HOME_USE_INDEX			2
#define HOME_IS_SHARED			4
#define HOME_UNLOCK_FIRST		8	/* LOCKING_INDEXER */
#define HOME_ABSOLUTE_ENCODER		16
#define HOME_NO_REHOME			32
#define HOME_NO_FINAL_MOVE		64
#define HOME_INDEX_NO_ENCODER_RESET	128

/* HOME_SEQUENCE values with |seq| above this take no part in Home-All (task sends 999
 * for a joint without HOME_SEQUENCE; it is also the default before any params). */
#define HOME_SEQUENCE_MAX 100
#define HOME_SEQUENCE_NONE 999

/* joint.N.home-state values (2.9 numbering, motion.md 9.4). */
enum home_state {
	HOME_IDLE = 0,
	HOME_START = 1,
	HOME_UNLOCK = 2,
	HOME_UNLOCK_WAIT = 3,
	HOME_INITIAL_BACKOFF_START = 4,
	HOME_INITIAL_BACKOFF_WAIT = 5,
	HOME_INITIAL_SEARCH_START = 6,
	HOME_INITIAL_SEARCH_WAIT = 7,
	HOME_SET_COARSE_POSITION = 8,
	HOME_FINAL_BACKOFF_START = 9,
	HOME_FINAL_BACKOFF_WAIT = 10,
	HOME_RISE_SEARCH_START = 11,
	HOME_RISE_SEARCH_WAIT = 12,
	HOME_FALL_SEARCH_START = 13,
	HOME_FALL_SEARCH_WAIT = 14,
	HOME_SET_SWITCH_POSITION = 15,
	HOME_INDEX_ONLY_START = 16,
	HOME_INDEX_SEARCH_START = 17,
	HOME_INDEX_SEARCH_WAIT = 18,
	HOME_SET_INDEX_POSITION = 19,
	HOME_FINAL_MOVE_START = 20,
	HOME_FINAL_MOVE_WAIT = 21,
	HOME_LOCK = 22,
	HOME_LOCK_WAIT = 23,
	HOME_FINISHED = 24,
	HOME_ABORT = 25
};

/* motion_state numbers set_unhomed() takes (motion.md 6). */
#define HOMING_MOTION_DISABLED 0
#define HOMING_MOTION_FREE 1
#define HOMING_MOTION_TELEOP 2
#define HOMING_MOTION_COORD 3

/* One joint as homing sees it. motmod owns the array (num_joints entries, passed to
 * homing_init) and fills/reads it around do_homing() every FREE period. Positions in
 * machine units, velocities in units/s.
 *   "motmod ->": motmod writes before do_homing(), homing only reads.
 *   "homing ->": homing writes inside do_homing(), motmod reads afterwards.
 *   "both":      motmod writes its current value before, homing may change it (homing
 *                moves the joint's coordinate system: set coarse/switch/index position),
 *                motmod takes the value back afterwards. */
struct homing_joint {
	/* motmod -> : joint flags and configuration */
	bool active;		/* JOINT_ACTIVATE'd: inactive joints never home, not in allhomed */
	bool enabled;		/* joint ENABLE flag (motion enabled) */
	bool on_pos_limit;	/* joint.N.pos-lim-sw-in as motion sees it this period */
	bool on_neg_limit;	/* joint.N.neg-lim-sw-in */
	bool free_tp_active;	/* free planner still moving (curr vel != 0 or not at target) */
	bool pad_[3];
	double max_vel;		/* [JOINT_n]MAX_VELOCITY: homing speeds are clamped to it */
	double max_acc;		/* [JOINT_n]MAX_ACCELERATION (for motmod's planner; informative) */
	double min_limit;	/* soft limits: a homing move's target is */
	double max_limit;	/* pos_cmd +- 2 * (max_limit - min_limit) */
	double motor_pos_fb;	/* joint.N.motor-pos-fb this period (index position) */
	double backlash_filt;	/* joint.N.backlash-filt (pos_fb = motor_pos_fb - filt - offset) */
	/* both */
	double pos_cmd;		/* joint.N.pos-cmd */
	double pos_fb;		/* joint.N.pos-fb */
	double motor_offset;	/* joint.N.motor-offset */
	double free_pos;	/* the free planner's current position (simple_tp curr_pos) */
	/* homing -> : motmod copies these three back after EVERY do_homing(), whatever
	 * get_homing(j) says. Homing changes them only for a joint it homes, but also in
	 * the period that ends the homing: an abort (limit, end of move, bad switch)
	 * stops the planner (free_tp_enable = FALSE) and an absolute-encoder home shifts
	 * free_pos_cmd, both in a period after which get_homing(j) is already FALSE.
	 * Otherwise homing leaves them as motmod wrote them. */
	double free_pos_cmd;	/* free planner target (joint.N.free-pos-cmd) */
	double free_vel_lim;	/* free planner velocity limit (joint.N.free-vel-lim) */
	bool free_tp_enable;	/* free planner enable (joint.N.free-tp-enable); FALSE = stop */
	bool pad2_[7];
};

/* Report function for errors: one line, no trailing newline, realtime context. */
typedef void (*homing_report_fn)(const char *msg);

/* Init (non-realtime, in rtapi_app_main; no FP). comp_id: motmod's component;
 * num_joints 1..HOMING_MAX_JOINTS; num_extrajoints 0..num_joints (the last ones: they
 * may be unhomed only while disabled); unlock_joints_mask: bit n creates joint.n.unlock
 * and joint.n.is-unlocked; joints: motmod's array of num_joints entries (must stay
 * valid until unload); report: error sink (NULL: rtapi_print_msg). Creates the pins
 * listed at the top. Returns 0 or -errno (a message names the failing pin). */
int homing_init(int comp_id, int num_joints, int num_extrajoints, rtapi_u32 unlock_joints_mask,
		struct homing_joint *joints, homing_report_fn report);

/* Copy the IN/IO pins to homing's state (start of motion-controller) and the OUT/IO
 * pins from it (end of motion-controller). No FP. */
void read_homing_in_pins(void);
void write_homing_out_pins(void);

/* --- FP (homing_fp.c) --- */

/* SET_JOINT_HOMING_PARAMS: HOME_OFFSET, HOME, HOME_FINAL_VEL, HOME_SEARCH_VEL,
 * HOME_LATCH_VEL, flags (HOME_* bits above), HOME_SEQUENCE (HOME_SEQUENCE_NONE when
 * absent), VOLATILE_HOME. Ignored for a joint that is homing. */
void set_joint_homing_params(int jno, double home_offset, double home, double home_final_vel,
			     double home_search_vel, double home_latch_vel, int home_flags,
			     int home_sequence, bool volatile_home);
/* UPDATE_JOINT_HOMING_PARAMS (ini.N.home, ini.N.home_offset, ini.N.home_sequence). */
void update_joint_homing_params(int jno, double home_offset, double home, int home_sequence);

/* JOINT_HOME: jno >= 0 one joint (a joint with a negative sequence homes its whole
 * synchronized group), -1 Home-All. Motion's preconditions are the caller's (above).
 * Returns 0 when homing started, -EINVAL for a bad joint number, -EBUSY when refused
 * (already homing or a Home-All running; a closed shared switch is reported when the
 * joint starts, in do_homing()), 1 when there is
 * nothing to do (NO_REHOME joint already homed, Home-All with no joint). */
int do_home_joint(int jno);
/* Stop homing of joint jno (-1: every joint, and any Home-All/sequence): the joint
 * goes through ABORT (homed and homing FALSE, index-enable FALSE). Called outside
 * do_homing(), it cannot reach motmod's free planner: motmod stops the planners of
 * the joints it cancels itself (it does so on disable and ABORT anyway). A joint of
 * a synchronized group takes its group with it. */
void do_cancel_homing(int jno);
/* JOINT_UNHOME: jno >= 0 one joint, -1 all, -2 only VOLATILE_HOME joints. Refused
 * (error reported, -EBUSY) while any homing is active or the joint's free planner moves. */
int do_unhome_joint(int jno);
/* Unhome one joint (jno >= 0) or all (-1) or volatile ones (-2) given motion's state
 * (HOMING_MOTION_*): extra joints are unhomed only when DISABLED. Returns as
 * do_unhome_joint(). */
int set_unhomed(int jno, int motion_state);
/* Run one period (FREE state only). period_ns: the servo period (times HOME_DELAY).
 * Returns true in the period in which "all homed" became true. */
bool do_homing(long period_ns);
/* A probe trip cancels homing: unless no_probe_home_error (the probe may be a home
 * switch then), if get_homing_is_active(): cancel all and report "Probe tripped
 * during homing motion.". Returns true when it cancelled. Like do_cancel_homing(),
 * called outside do_homing(): motmod then stops the free planners of the joints
 * that were homing itself (or they run on to the far end of the search move). */
bool homing_probe_trip(bool no_probe_home_error);

/* --- getters (homing_core.c, no FP), j = joint number --- */
bool get_allhomed(void);			/* every active joint homed */
bool get_homed(int j);
bool get_home_is_idle(int j);			/* home-state IDLE */
bool get_home_is_synchronized(int j);		/* negative HOME_SEQUENCE */
bool get_home_needs_unlock_first(int j);	/* LOCKING_INDEXER */
bool get_homing(int j);				/* joint.N.homing */
bool get_homing_at_index_search_wait(int j);	/* in INDEX_SEARCH_WAIT */
bool get_homing_is_active(void);		/* any joint homing or a sequence running */
bool get_index_enable(int j);			/* joint.N.index-enable as last read/set */
int get_home_sequence(int j);
bool get_home_is_volatile(int j);
int get_home_state(int j);			/* enum home_state */

#ifdef __cplusplus
}
#endif
#endif
