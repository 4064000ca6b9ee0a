/* SPDX-License-Identifier: GPL-2.0-or-later */
/* motion_if.h - the command/status channel between userspace (task, motcmd, the C++
 * client in user/motion/) and motmod: one shared-memory block (rtapi_shmem, key =
 * motmod's `key` parameter, default 100) holding
 *   struct motion_if_hdr     magic, layout version, size, the writer claim
 *   struct motion_command    the command slot (userspace writes, the handler reads)
 *   struct motion_status     what motion publishes every servo period
 *   struct motion_error_ring queued error messages (motion writes, userspace drains)
 *
 * Command protocol (motion.md 7):
 *  1. A writer claims the channel: compare-and-swap hdr.writer_pid from 0 (or from a
 *     pid that no longer exists) to its pid; a live other pid means "another writer".
 *     Motion does not rely on the claim: it is the writers' courtesy to each other.
 *  2. It fills every field of the command slot, then (release barrier) stores
 *     commandNum = status.commandNumEcho + 1.
 *  3. motion-command-handler sees commandNum != the last number it handled, copies the
 *     slot (so a writer changing it meanwhile cannot change what was checked), stores
 *     commandNumEcho = commandNum, and, when the number is the last one + 1, checks and
 *     runs the command; commandStatus = MOTION_CMD_OK / UNKNOWN / INVALID /
 *     INVALID_PARAMS / BAD_EXEC. A number out of sequence (a writer that did not read
 *     the echo, garbage) is answered MOTION_CMD_INVALID with an error message and not
 *     run; the next writer continues from the echo.
 *  4. The writer polls status.commandNumEcho until it equals its number (timeout: the
 *     thread is not running), then reads commandStatus.
 * Every field the handler uses is checked (joint/axis/spindle/io indices, counts,
 * finite numbers, enum values) before it is used: a hostile local user who writes the
 * block can get commands refused, never a crash or corrupted motion state.
 *
 * Status: the controller increments status.head at the start of its update and stores
 * status.tail = head at the end. A reader copies the block and retries until head ==
 * tail before and after its copy (split-read detection).
 *
 * Errors: motion writes message number error.head % MOTION_ERR_NUM, then increments
 * head; a reader takes messages from error.tail up to head and stores tail. When
 * head - tail reaches MOTION_ERR_NUM the ring is full: a newer message is not written
 * and error.overflow counts it (nothing already queued is lost).
 *
 * Units: machine units and degrees, seconds. Arrays are sized by the compile-time
 * maxima below; num_joints etc. in the status say how many are in use. */
#ifndef MOTION_IF_H
#define MOTION_IF_H

#include "rtapi.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MOTION_IF_MAGIC 0x4d4f5449u	/* "MOTI" */
#define MOTION_IF_VERSION 1u
#define MOTION_DEFAULT_KEY 100

#define MOTION_MAX_JOINTS 16		/* EMCMOT_MAX_JOINTS */
#define MOTION_MAX_AXES 9		/* X Y Z A B C U V W */
#define MOTION_MAX_SPINDLES 8
#define MOTION_MAX_DIO 64
#define MOTION_MAX_AIO 64
#define MOTION_MAX_MISC_ERRORS 64
#define MOTION_COMP_SIZE 256		/* comp-table points per joint */
#define MOTION_ERR_NUM 32
#define MOTION_ERR_LEN 256

/* Command numbers: the 2.9 enum order (ABORT = 1), motion.md 7.1. */
enum motion_cmd_type {
	MOTCMD_ABORT = 1,
	MOTCMD_ENABLE,
	MOTCMD_DISABLE,
	MOTCMD_PAUSE,
	MOTCMD_REVERSE,
	MOTCMD_FORWARD,
	MOTCMD_RESUME,
	MOTCMD_STEP,
	MOTCMD_FREE,
	MOTCMD_COORD,
	MOTCMD_TELEOP,
	MOTCMD_SPINDLE_SCALE,
	MOTCMD_SS_ENABLE,
	MOTCMD_FEED_SCALE,
	MOTCMD_RAPID_SCALE,
	MOTCMD_FS_ENABLE,
	MOTCMD_FH_ENABLE,
	MOTCMD_AF_ENABLE,
	MOTCMD_OVERRIDE_LIMITS,
	MOTCMD_SET_LINE,
	MOTCMD_SET_CIRCLE,
	MOTCMD_SET_TELEOP_VECTOR,
	MOTCMD_CLEAR_PROBE_FLAGS,
	MOTCMD_PROBE,
	MOTCMD_RIGID_TAP,
	MOTCMD_SET_VEL,
	MOTCMD_SET_VEL_LIMIT,
	MOTCMD_SET_ACC,
	MOTCMD_SET_TERM_COND,
	MOTCMD_SET_NUM_JOINTS,
	MOTCMD_SET_NUM_SPINDLES,
	MOTCMD_SET_WORLD_HOME,
	MOTCMD_SET_DEBUG,
	MOTCMD_SET_DOUT,
	MOTCMD_SET_AOUT,
	MOTCMD_SET_SPINDLESYNC,
	MOTCMD_SPINDLE_ON,
	MOTCMD_SPINDLE_OFF,
	MOTCMD_SPINDLE_INCREASE,
	MOTCMD_SPINDLE_DECREASE,
	MOTCMD_SPINDLE_BRAKE_ENGAGE,
	MOTCMD_SPINDLE_BRAKE_RELEASE,
	MOTCMD_SPINDLE_ORIENT,
	MOTCMD_SET_OFFSET,
	MOTCMD_SET_MAX_FEED_OVERRIDE,
	/* [TRAJ]ARC_BLEND_*: mode = enable, flags = fallback enable, count = optimization
	 * depth, value = gap cycles, scale = ramp frequency (Hz), tolerance = tangent kink
	 * ratio */
	MOTCMD_SETUP_ARC_BLENDS,
	MOTCMD_SET_PROBE_ERR_INHIBIT,
	MOTCMD_ENABLE_WATCHDOG,
	MOTCMD_DISABLE_WATCHDOG,
	MOTCMD_JOG_CONT,
	MOTCMD_JOG_INCR,
	MOTCMD_JOG_ABS,
	MOTCMD_JOG_ABORT,
	MOTCMD_JOINT_ACTIVATE,
	MOTCMD_JOINT_DEACTIVATE,
	MOTCMD_JOINT_ENABLE_AMPLIFIER,
	MOTCMD_JOINT_DISABLE_AMPLIFIER,
	MOTCMD_JOINT_HOME,
	MOTCMD_JOINT_UNHOME,
	MOTCMD_SET_JOINT_POSITION_LIMITS,
	MOTCMD_SET_JOINT_BACKLASH,
	MOTCMD_SET_JOINT_MIN_FERROR,
	MOTCMD_SET_JOINT_MAX_FERROR,
	MOTCMD_SET_JOINT_VEL_LIMIT,
	MOTCMD_SET_JOINT_ACC_LIMIT,
	MOTCMD_SET_JOINT_HOMING_PARAMS,
	MOTCMD_UPDATE_JOINT_HOMING_PARAMS,
	MOTCMD_SET_JOINT_MOTOR_OFFSET,
	MOTCMD_SET_JOINT_COMP,
	MOTCMD_SET_AXIS_POSITION_LIMITS,
	MOTCMD_SET_AXIS_VEL_LIMIT,
	MOTCMD_SET_AXIS_ACC_LIMIT,
	MOTCMD_SET_AXIS_LOCKING_JOINT,
	MOTCMD_SET_SPINDLE_PARAMS,
	/* added after LinuxCNC 2.9's list: the external-offset velocity (vel) and
	 * acceleration (acc) of axis 'axis', task's OFFSET_AV_RATIO share of the axis
	 * limits (2.9 sends them with SET_AXIS_VEL/ACC_LIMIT); 0 = no external offset */
	MOTCMD_SET_AXIS_EXT_OFFSET_LIMITS,
	MOTCMD_LAST = MOTCMD_SET_AXIS_EXT_OFFSET_LIMITS
};

/* commandStatus */
enum motion_cmd_status {
	MOTION_CMD_OK = 0,
	MOTION_CMD_UNKNOWN = 1,		/* command number not in the enum */
	MOTION_CMD_INVALID = 2,		/* not allowed now, or out of sequence */
	MOTION_CMD_INVALID_PARAMS = 3,	/* a field out of range / not finite */
	MOTION_CMD_BAD_EXEC = 4		/* accepted but could not be carried out */
};

/* motion_state (motion.md 6) */
enum motion_state { MOTION_DISABLED = 0, MOTION_FREE = 1, MOTION_TELEOP = 2, MOTION_COORD = 3 };

/* motionFlag bits */
#define MOTION_FLAG_ENABLE 0x01
#define MOTION_FLAG_INPOS 0x02
#define MOTION_FLAG_COORD 0x04
#define MOTION_FLAG_ERROR 0x08
#define MOTION_FLAG_TELEOP 0x10

/* joint flag bits */
#define JOINT_FLAG_ENABLE 0x01
#define JOINT_FLAG_ACTIVE 0x02
#define JOINT_FLAG_INPOS 0x04
#define JOINT_FLAG_ERROR 0x08
#define JOINT_FLAG_MAX_HARD_LIMIT 0x10
#define JOINT_FLAG_MIN_HARD_LIMIT 0x20
#define JOINT_FLAG_FERROR 0x40
#define JOINT_FLAG_FAULT 0x80

/* enables_new bits (M48-M53) */
#define MOTION_SS_ENABLED 0x01
#define MOTION_FS_ENABLED 0x02
#define MOTION_AF_ENABLED 0x04
#define MOTION_FH_ENABLED 0x08

/* term conditions (SET_TERM_COND) */
#define MOTION_TERM_STOP 0
#define MOTION_TERM_EXACT 1
#define MOTION_TERM_PARABOLIC 2

/* motion types (motion.motion-type, SET_LINE motion_type) */
#define MOTION_TYPE_TRAVERSE 1
#define MOTION_TYPE_FEED 2
#define MOTION_TYPE_ARC 3
#define MOTION_TYPE_TOOLCHANGE 4
#define MOTION_TYPE_PROBING 5
#define MOTION_TYPE_INDEXROTARY 6

/* a world position: x y z a b c u v w (index = axis number) */
struct motion_pose {
	double v[MOTION_MAX_AXES];
};

/* The command slot. Which fields a command reads: motion.md 7.1 and docs/motion.md. */
struct motion_command {
	rtapi_s32 command;		/* enum motion_cmd_type */
	rtapi_u32 commandNum;		/* written last by the writer */
	rtapi_s32 joint;		/* joint number, -1 all (home/unhome), -2 volatile */
	rtapi_s32 axis;			/* axis number 0..8 (teleop jogs), -1 none */
	rtapi_s32 spindle;		/* spindle number, -1 all */
	rtapi_s32 id;			/* line number of a queued move */
	rtapi_s32 motion_type;
	rtapi_s32 turn;			/* arcs: extra full turns */
	rtapi_s32 termCond;
	rtapi_s32 flags;		/* homing flags, spindle-sync velocity mode */
	rtapi_s32 home_sequence;
	rtapi_s32 volatile_home;
	rtapi_s32 out;			/* DIO/AIO index */
	rtapi_s32 now;			/* SET_DOUT/AOUT: immediate */
	rtapi_s32 start;		/* SET_DOUT: state at segment start */
	rtapi_s32 end;			/* SET_DOUT: state at segment end */
	rtapi_s32 mode;			/* enable commands: 0/1; SPINDLE_ORIENT: mode */
	rtapi_s32 probe_type;
	rtapi_s32 wait_for_at_speed;
	rtapi_s32 count;		/* SET_NUM_JOINTS / SPINDLES; SET_DEBUG level */
	rtapi_s32 pad_;
	struct motion_pose pos;		/* target / tool offset / world home */
	double center[3];
	double normal[3];
	double vel;			/* velocity, jog velocity (signed for JOG_CONT) */
	double ini_maxvel;
	double acc;
	double tolerance;
	double offset;			/* jog distance / position, home offset, motor offset */
	double home;
	double home_final_vel;
	double search_vel;
	double latch_vel;
	double minLimit;
	double maxLimit;
	double value;			/* backlash, ferror, joint/axis vel/acc limit, scale */
	double scale;			/* overrides; rigid-tap reversal scale */
	double aout_start;		/* SET_AOUT values */
	double aout_end;
	double comp_nominal;
	double comp_forward;
	double comp_reverse;
	double spindlesync;		/* units per revolution */
	double css_factor;
	double xoffset;
	double orientation;		/* degrees */
	double spindle_params[5];	/* min_fwd max_fwd min_rev max_rev increment (rpm) */
};

struct motion_joint_status {
	rtapi_u32 flag;			/* JOINT_FLAG_* */
	rtapi_s32 homing;
	rtapi_s32 homed;
	rtapi_s32 home_state;
	double pos_cmd;
	double pos_fb;
	double vel_cmd;
	double acc_cmd;
	double ferror;
	double ferror_high_mark;
	double ferror_limit;
	double backlash;
	double min_pos_limit;
	double max_pos_limit;
	double min_ferror;
	double max_ferror;
	double vel_limit;
	double acc_limit;
	double motor_offset;
	rtapi_s32 comp_entries;
	rtapi_s32 pad_;
};

struct motion_axis_status {
	double pos_cmd;
	double teleop_vel_cmd;
	double min_pos_limit;
	double max_pos_limit;
	double vel_limit;
	double acc_limit;
};

struct motion_spindle_status {
	double speed;			/* commanded rpm (signed) */
	double scale;			/* spindle override */
	double net_scale;
	double css_factor;
	double xoffset;
	double speed_out;		/* spindle.S.speed-out */
	double revs;
	double speed_in;
	rtapi_s32 state;
	rtapi_s32 direction;
	rtapi_s32 brake;
	rtapi_s32 locked;
	rtapi_s32 orient_fault;
	rtapi_s32 orient_state;		/* 0 none, 1 in progress, 2 complete, 3 fault */
	rtapi_s32 at_speed;
	rtapi_s32 fault;
};

struct motion_status {
	rtapi_u32 head;
	rtapi_u32 commandNumEcho;
	rtapi_s32 commandEcho;
	rtapi_s32 commandStatus;
	rtapi_u32 heartbeat;
	rtapi_s32 motion_state;		/* enum motion_state */
	rtapi_u32 motionFlag;
	rtapi_s32 paused;
	rtapi_s32 stepping;
	rtapi_s32 reverse_run;
	rtapi_u32 overrideLimitMask;
	rtapi_s32 on_soft_limit;
	rtapi_s32 jogging_active;
	rtapi_s32 enables_new;
	rtapi_s32 all_homed;
	rtapi_s32 num_joints;
	rtapi_s32 num_extrajoints;
	rtapi_s32 num_spindles;
	rtapi_s32 num_dio;
	rtapi_s32 num_aio;
	rtapi_s32 num_misc_error;
	rtapi_s32 kinematics_type;
	rtapi_s32 carte_pos_fb_ok;
	rtapi_s32 id;			/* executing line */
	rtapi_s32 depth;		/* queued segments */
	rtapi_s32 activeDepth;
	rtapi_s32 queueFull;
	rtapi_s32 motionType;
	rtapi_s32 probeVal;
	rtapi_s32 probeTripped;
	rtapi_s32 probing;
	rtapi_s32 probe_type;
	rtapi_s32 pad_;
	double feed_scale;
	double rapid_scale;
	double net_feed_scale;
	double distance_to_go;
	double current_vel;
	double requested_vel;
	double vel;			/* SET_VEL */
	double acc;			/* SET_ACC */
	double vel_limit;		/* SET_VEL_LIMIT */
	struct motion_pose carte_pos_cmd;
	struct motion_pose carte_pos_fb;
	struct motion_pose world_home;
	struct motion_pose probedPos;
	struct motion_pose tool_offset;
	struct motion_joint_status joint[MOTION_MAX_JOINTS];
	struct motion_axis_status axis[MOTION_MAX_AXES];
	struct motion_spindle_status spindle[MOTION_MAX_SPINDLES];
	rtapi_u8 synch_di[MOTION_MAX_DIO];
	rtapi_u8 synch_do[MOTION_MAX_DIO];
	rtapi_u8 misc_error[MOTION_MAX_MISC_ERRORS];
	double analog_input[MOTION_MAX_AIO];
	double analog_output[MOTION_MAX_AIO];
	rtapi_u32 tail;
	rtapi_u32 pad2_;
};

struct motion_error_ring {
	rtapi_u32 head;			/* motion: messages written */
	rtapi_u32 tail;			/* readers: messages taken */
	rtapi_u32 overflow;		/* messages not queued because the ring was full */
	rtapi_u32 pad_;
	char msg[MOTION_ERR_NUM][MOTION_ERR_LEN];
};

struct motion_if_hdr {
	rtapi_u32 magic;		/* MOTION_IF_MAGIC once motmod has set the block up */
	rtapi_u32 version;		/* MOTION_IF_VERSION */
	rtapi_u32 size;			/* sizeof(struct motion_shmem) */
	rtapi_s32 writer_pid;		/* the claiming writer (0 = none) */
};

struct motion_shmem {
	struct motion_if_hdr hdr;
	struct motion_command command;
	struct motion_status status;
	struct motion_error_ring error;
};

#ifdef __cplusplus
}
#endif
#endif /* MOTION_IF_H */
