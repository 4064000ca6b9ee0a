/* SPDX-License-Identifier: GPL-2.0-or-later */
/* homing_priv.h - homing's own state, shared by homing_core.c (setup, getters),
 * homing_pins.c (HAL pins) and homing_fp.c (the state machine). Not for motmod: it
 * uses homing.h. The unit tests drive the pin mirrors (home_sw, index_enable,
 * is_unlocked) directly, without a HAL. */
#ifndef HOMING_PRIV_H
#define HOMING_PRIV_H

#include "homing.h"

/* Pause before every homing move, after the free planner has stopped (motion.md 9.3). */
#define HOME_DELAY_NS 100000000LL

/* Home-All / sequence states (motion.md 9.5). */
enum home_seq_state {
	HOME_SEQ_IDLE = 0,
	HOME_SEQ_START_JOINTS,		/* start every joint of the current sequence */
	HOME_SEQ_WAIT_JOINTS		/* wait until they are all idle again */
};

/* One joint's homing state. Pin mirrors are written by read_homing_in_pins() or by the
 * state machine and copied out by write_homing_out_pins(); the rest is private to the
 * state machine (servo thread) and the command handler (same thread). */
struct homing_priv {
	/* pin mirrors */
	bool home_sw;		/* joint.N.home-sw-in (in) */
	bool index_enable;	/* joint.N.index-enable (io): set by homing, cleared by the encoder */
	bool is_unlocked;	/* joint.N.is-unlocked (in) */
	bool unlock;		/* joint.N.unlock (out) */
	bool homing;		/* joint.N.homing (out) */
	bool homed;		/* joint.N.homed (out) */
	/* configuration (SET/UPDATE_JOINT_HOMING_PARAMS) */
	bool volatile_home;
	bool sync_ready;	/* synchronized group: this joint waits at FINAL_MOVE_START */
	bool move_started;	/* a move was started for it in this do_homing() call */
	int state;		/* enum home_state, joint.N.home-state */
	int flags;		/* HOME_* bits */
	int sequence;		/* HOME_SEQUENCE (normalised: a group with one negative is negative) */
	int sequence_raw;	/* HOME_SEQUENCE as given */
	rtapi_s64 pause_ns;	/* time stopped so far before the next move */
	double home_offset;	/* HOME_OFFSET */
	double home;		/* HOME */
	double final_vel;	/* HOME_FINAL_VEL */
	double search_vel;	/* HOME_SEARCH_VEL */
	double latch_vel;	/* HOME_LATCH_VEL */
};

struct homing_global {
	int num_joints;
	int num_extrajoints;	/* the last num_extrajoints joints */
	rtapi_u32 unlock_mask;
	int seq_state;		/* enum home_seq_state */
	int seq_current;	/* sequence number being homed */
	bool seq_home_all;	/* Home-All (go on to the next sequence) or one group only */
	bool pad_[3];
	rtapi_u32 seq_skip;	/* Home-All: joints not homed again (NO_REHOME and homed) */
	struct homing_joint *joints;	/* motmod's array */
	homing_report_fn report;
	struct homing_priv h[HOMING_MAX_JOINTS];
};

/* The one instance (motmod is loaded once). Defined in homing_core.c. */
extern struct homing_global homing_g;

/* Setup without HAL (homing_init calls it; the unit tests call it directly):
 * every joint idle, unhomed, HOME_SEQUENCE_NONE, other params zero. No FP. */
int homing_setup(int num_joints, int num_extrajoints, rtapi_u32 unlock_joints_mask,
		 struct homing_joint *joints, homing_report_fn report);
/* Report one error line (printf format, no floats: the kernel flavor cannot format them). */
void homing_report(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* |seq| of joint j (sequences compare by magnitude). */
static inline int homing_seq_abs(int j)
{
	int s = homing_g.h[j].sequence;

	return s < 0 ? -s : s;
}

#endif
