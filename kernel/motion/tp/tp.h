/* tp.h - the coordinated trajectory planner of motmod (G0/G1/G2/G3/G33/G38/G33.1).
 *
 * Pure C with no HAL and no global state: every function works on a struct tp whose
 * memory the caller provides (tp_size() bytes, obtained once at load time; the planner
 * never allocates).  motmod calls tp_run_cycle() once per trajectory period from
 * motion-controller in COORD mode, and the tp_add_* / tp_set_* functions from
 * motion-command-handler.  Nothing here locks: the caller serialises (both motmod
 * functions run in the same servo thread).
 *
 * Floating point: every function here (including tp_size/tp_init) is compiled in
 * *_fp.c units; call them from a realtime function exported with uses_fp = 1, or
 * between rtapi_fpu_begin() and rtapi_fpu_end() at init time.
 *
 * Return values: 0 on success, a negative TP_ERR_* code on failure (tp_strerror()
 * gives the text).  A failed call changes nothing.
 *
 * Stability: this header is the contract with motmod.  Changes are additive only. */
#ifndef TP_H
#define TP_H

#include "rtapi.h"		/* rtapi_u64 */
#include "tp_pose.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- constants ---------------------------------------------------------------- */

#define TP_DEFAULT_QUEUE_SIZE	2000	/* segments ([TRAJ] queue of LinuxCNC 2.9) */
#define TP_MIN_QUEUE_SIZE	4
#define TP_MAX_QUEUE_SIZE	100000
#define TP_DEFAULT_OPT_DEPTH	50	/* ARC_BLEND_OPTIMIZATION_DEPTH */
#define TP_MAX_DIO		64	/* synchronized digital outputs (motion.digital-out-NN) */
#define TP_MAX_AIO		64	/* synchronized analog outputs (motion.analog-out-NN) */
#define TP_SEG_AIO_MAX		8	/* distinct analog outputs one segment start may change */

/* Motion types as reported in status (EMC_MOTION_TYPE_* values of LinuxCNC). */
enum tp_motion_type {
	TP_MOTION_NONE = 0,
	TP_MOTION_TRAVERSE = 1,		/* G0 */
	TP_MOTION_FEED = 2,		/* G1, G33, G33.1 */
	TP_MOTION_ARC = 3,		/* G2/G3 */
	TP_MOTION_TOOLCHANGE = 4,
	TP_MOTION_PROBING = 5,		/* G38.x */
	TP_MOTION_INDEXROTARY = 6,
};

/* Termination condition of a segment (motion.md §7, 2.9 numbering). */
enum tp_term_cond {
	TP_TERM_STOP = 0,		/* G61.1: stop at every segment end */
	TP_TERM_EXACT = 1,		/* G61: stop at corners, keep speed through tangent junctions */
	TP_TERM_PARABOLIC = 2,		/* G64 [P tol]: blend */
	TP_TERM_TANGENT = 3,		/* internal: junction found tangent, keep speed */
};

/* Spindle synchronisation of a segment (SET_SPINDLESYNC). */
enum tp_sync_mode {
	TP_SYNC_NONE = 0,
	TP_SYNC_VELOCITY = 1,		/* G95 feed per revolution */
	TP_SYNC_POSITION = 2,		/* G33/G76 threading, rigid tap */
};

/* Probe type bits (PROBE command). */
#define TP_PROBE_NO_ERROR	0x1	/* G38.3/G38.5: no error if no contact */
#define TP_PROBE_LOSS		0x2	/* G38.4/G38.5: trip on contact loss (input 0) */

/* Error codes (negative returns). */
enum tp_err {
	TP_OK = 0,
	TP_ERR_INVALID = -1,		/* bad argument (NaN, non-positive limit, bad index...) */
	TP_ERR_QUEUE_FULL = -2,		/* segment queue full */
	TP_ERR_NO_MEMORY = -3,		/* tp_init: memory smaller than tp_size(queue_size) */
	TP_ERR_BUSY = -4,		/* not allowed while moving (e.g. step while executing) */
	TP_ERR_ABORTING = -5,		/* segment refused: abort in progress */
	TP_ERR_ZERO_LENGTH = -6,	/* (not an error for lines: zero-length lines are dropped, 0 returned) */
	TP_ERR_NO_SYNC = -7,		/* rigid tap without SET_SPINDLESYNC units per rev */
};

/* ---- the planner ---------------------------------------------------------------- */

struct tp;	/* opaque; lives in caller-provided memory of tp_size() bytes */

/* Per-segment move data common to every tp_add_* (one SET_LINE / SET_CIRCLE /
 * PROBE / RIGID_TAP command). */
struct tp_move {
	int motion_type;		/* enum tp_motion_type */
	double vel;			/* requested velocity (F, units/s); traverses: the segment limit */
	double ini_maxvel;		/* kinematic velocity bound of this segment (canon) */
	double acc;			/* acceleration bound of this segment (canon) */
	int id;				/* line number, reported while executing */
	int tag;			/* interpreter state tag, reported while executing */
	unsigned char enables;		/* FS 0x02, AF 0x04, FH 0x08 ... reported as enables_queued */
	int atspeed;			/* wait for spindle at-speed before starting */
	int probe_type;			/* TP_PROBE_* bits, motion_type TP_MOTION_PROBING only */
};

/* Inputs of one planner cycle (motmod's process_inputs results). */
struct tp_inputs {
	double feed_scale;		/* net feed scale for feeds/arcs/probes (override x adaptive; 0 on feed hold) */
	double rapid_scale;		/* net scale for traverses (rapid override; 0 on feed hold) */
	double spindle_revs;		/* spindle.S.revs of the synchronising spindle */
	double spindle_speed;		/* spindle.S.speed-in, rev/s (signed) */
	int spindle_at_speed;		/* spindle.S.at-speed */
	int spindle_index_enable;	/* spindle.S.index-enable as read back this period */
	int probe_input;		/* motion.probe-input */
};

/* Synchronized analog output change (value at the segment start; end: the value at
 * its end, used when has_end). */
struct tp_aout {
	int index;
	double value;
	int has_end;
	double end;
};

/* Outputs of one planner cycle. */
struct tp_outputs {
	struct tp_pose pos;		/* new commanded world position */
	double current_vel;		/* path speed this cycle (units/s) */
	double requested_vel;		/* requested speed of the executing segment */
	double acc;			/* path acceleration this cycle */
	double distance_to_go;		/* along the executing segment */
	struct tp_pose dtg;		/* remaining per-axis distance of the executing segment */
	int exec_id;			/* line id of the executing segment (0 if idle) */
	int exec_tag;
	int motion_type;		/* enum tp_motion_type of the executing segment, 0 idle */
	unsigned char enables_queued;	/* enables of the executing segment */
	int done;			/* queue empty and stopped */
	int queue_depth;		/* segments queued (including executing) */
	int active_depth;		/* segments currently moving (1, 2 while blending) */
	int queue_full;
	int paused;			/* pause requested and motion stopped */
	/* Synchronized outputs to apply this period (a segment's start values, or the end
	 * values of one that ended; a segment starting in the same period comes after). */
	rtapi_u64 dout_mask;		/* bit i set: motion.digital-out-i := bit i of dout_value */
	rtapi_u64 dout_value;
	int aout_count;
	struct tp_aout aout[TP_SEG_AIO_MAX];
	/* Spindle synchronisation. */
	int spindle_sync;		/* the head segment is spindle-synchronized (waiting or moving) */
	int spindle_num;		/* spindle of that segment */
	int spindle_index_request;	/* set spindle.S.index-enable this period (position sync start) */
	int waiting_for_index;		/* waiting for the index (spindle.S.index-enable to clear) */
	int waiting_for_atspeed;	/* waiting for spindle.S.at-speed */
	double spindle_speed_scale;	/* rigid tap: multiply the commanded spindle speed (1, or -reversal) */
	/* Probing. */
	int probing;			/* a probe segment is executing */
	int probe_tripped;		/* this cycle: probe tripped, planner aborting */
	int probe_no_contact;		/* this cycle: probe segment ended without a trip */
	struct tp_pose probed_pos;	/* commanded position at the trip (or at the end) */
};

/* Bytes needed for a planner with queue_size segments (0 if out of range). */
unsigned long tp_size(int queue_size);
/* Initialise mem (tp_size(queue_size) bytes, any alignment of 8) as a planner with
 * defaults: cycle 1 ms, vmax/vlimit/amax 1e99/1e99/1e99 (set them!), STOP, position 0,
 * max feed scale 1, arc blends on with fallback, opt depth 50, gap cycles 4, ramp 100 Hz,
 * kink ratio 0.1, no per-axis bounds.  Returns the planner or NULL. */
struct tp *tp_init(void *mem, unsigned long bytes, int queue_size);
const char *tp_strerror(int err);

/* Configuration (any time; take effect for following segments / next cycle). */
int tp_set_cycle_time(struct tp *tp, double secs);
int tp_set_vmax(struct tp *tp, double vmax, double ini_maxvel);	/* SET_VEL */
int tp_set_vlimit(struct tp *tp, double vlimit);			/* SET_VEL_LIMIT */
int tp_set_amax(struct tp *tp, double amax);				/* SET_ACC */
int tp_set_term_cond(struct tp *tp, int cond, double tolerance);	/* SET_TERM_COND */
int tp_set_max_feed_scale(struct tp *tp, double scale);		/* SET_MAX_FEED_OVERRIDE */
/* Per-axis bounds used for corner/kink checks and blend arcs (SET_AXIS_VEL/ACC_LIMIT). */
int tp_set_axis_limits(struct tp *tp, int axis, double vmax, double amax);
/* SETUP_ARC_BLENDS. */
int tp_set_arc_blend(struct tp *tp, int enable, int fallback_enable, int opt_depth,
		     int gap_cycles, double ramp_freq, double kink_ratio);
/* Position the planner is at (idle only: TP_ERR_BUSY if moving). */
int tp_set_pos(struct tp *tp, const struct tp_pose *pos);
int tp_get_pos(const struct tp *tp, struct tp_pose *pos);

/* Synchronized outputs of the next queued segment (M62-M67, motion.md 7.1 SET_DOUT/
 * SET_AOUT): start_value when it starts moving and, if end_value differs, end_value
 * when it reaches its end (an aborted segment does not reach it). */
int tp_set_dout(struct tp *tp, int index, int start_value, int end_value);
int tp_set_aout(struct tp *tp, int index, double start_value, double end_value);
/* G33/G95/G33.1 for following segments: units per spindle rev, 0 = off;
 * velocity_mode != 0: feed per rev (G95), else position sync (G33). */
int tp_set_spindle_sync(struct tp *tp, int spindle_num, double units_per_rev, int velocity_mode);

/* Queue segments. */
int tp_add_line(struct tp *tp, const struct tp_pose *end, const struct tp_move *mv);
/* Arc/helix from the current end to end, around the axis through center with
 * direction normal (right-hand: counter-clockwise seen from +normal);
 * turn = extra full turns (0 = less than one revolution). */
int tp_add_circle(struct tp *tp, const struct tp_pose *end, const struct tp_cart *center,
		  const struct tp_cart *normal, int turn, const struct tp_move *mv);
/* Rigid tap to end and back (needs tp_set_spindle_sync with units_per_rev != 0). */
int tp_add_rigid_tap(struct tp *tp, const struct tp_pose *end, double reversal_scale,
		     const struct tp_move *mv);

/* One planner cycle. */
int tp_run_cycle(struct tp *tp, const struct tp_inputs *in, struct tp_outputs *out);

/* Execution control. */
int tp_pause(struct tp *tp);		/* decelerate to 0, keep the queue */
int tp_resume(struct tp *tp);		/* clear pause and stepping */
int tp_step(struct tp *tp);		/* while paused: run to the end of the next segment, pause */
int tp_abort(struct tp *tp);		/* decelerate to 0, then clear the queue */
int tp_clear(struct tp *tp);		/* drop the queue now (idle / mode change) */

/* Status. */
int tp_is_done(const struct tp *tp);
int tp_queue_depth(const struct tp *tp);
int tp_active_depth(const struct tp *tp);
int tp_is_queue_full(const struct tp *tp);
int tp_is_paused(const struct tp *tp);
int tp_exec_id(const struct tp *tp);
/* The n-th queued segment (0 = executing): progress along it, current path speed and
 * its acceleration bound. TP_ERR_INVALID when fewer than n + 1 are queued. */
int tp_segment_info(const struct tp *tp, int n, double *progress, double *vel, double *acc);

#ifdef __cplusplus
}
#endif
#endif
