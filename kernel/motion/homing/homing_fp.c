/* SPDX-License-Identifier: GPL-2.0-or-later */
/* homing_fp.c - the homing state machine (motion.md 9): per-joint sequences with every
 * HOME_* option, Home-All and home sequences (negative = synchronized final move),
 * cancel, unhome and the homing parameters. Everything here runs in the servo thread
 * inside an FPU section (motmod's functions are uses_fp = 1), except
 * set_joint_homing_params() and friends, which motmod's command handler (also FP) calls.
 *
 * Each period do_homing() first advances the Home-All/sequence machine (which only
 * puts joints into HOME_START), then every joint's machine. A joint's machine may pass
 * several states in one period: "again" re-runs the switch for the new state. States
 * named *_START wait until the free planner has stopped plus HOME_DELAY, then start a
 * move; *_WAIT states wait for the move's event (switch edge, index) and abort when a
 * limit switch trips (unless HOME_IGNORE_LIMITS) or the move ends without the event. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "homing_priv.h"

static struct homing_joint *jt_of(int j)
{
	return &homing_g.joints[j];
}

static bool is_extra(int j)
{
	return j >= homing_g.num_joints - homing_g.num_extrajoints;
}

/* |vel| limited to the joint's MAX_VELOCITY (when that is set). */
static double clamp_speed(int j, double vel)
{
	double v = fabs(vel), max = jt_of(j)->max_vel;

	return (max > 0.0 && v > max) ? max : v;
}

/* A homing move: toward pos_cmd +- 2 x the joint's range, far enough that the event
 * (switch, index) comes first; reaching the end is an error. */
static void start_search_move(int j, double vel)
{
	struct homing_joint *jt = jt_of(j);
	double range = 2.0 * fabs(jt->max_limit - jt->min_limit);

	jt->free_pos_cmd = jt->pos_cmd + (vel > 0.0 ? range : -range);
	jt->free_vel_lim = clamp_speed(j, vel);
	jt->free_tp_enable = true;
	homing_g.h[j].move_started = true;
}

static void stop_move(int j)
{
	jt_of(j)->free_tp_enable = false;
}

/* True once the free planner has been stopped for HOME_DELAY; the time restarts
 * whenever it moves. Called once per period by the *_START states. */
static bool paused_enough(int j, long period_ns)
{
	struct homing_priv *h = &homing_g.h[j];

	if (jt_of(j)->free_tp_active) {
		h->pause_ns = 0;
		return false;
	}
	if (h->pause_ns < HOME_DELAY_NS) {
		h->pause_ns += period_ns;
		return false;
	}
	h->pause_ns = 0;
	return true;
}

/* Move the joint's coordinate system by 'offset' without moving the motor: the
 * position now reads offset more, the motor offset compensates. */
static void shift_position(int j, double offset)
{
	struct homing_joint *jt = jt_of(j);

	jt->pos_cmd += offset;
	jt->pos_fb += offset;
	jt->free_pos += offset;
	jt->free_pos_cmd += offset;
	jt->motor_offset -= offset;
}

/* The first state after START (and after UNLOCK): which sequence the search and latch
 * velocities ask for (motion.md 9.2). */
static int first_state(int j)
{
	struct homing_priv *h = &homing_g.h[j];

	if (h->flags & HOME_ABSOLUTE_ENCODER)
		return HOME_SET_SWITCH_POSITION;
	if (h->search_vel == 0.0) {
		if (h->latch_vel == 0.0)
			return HOME_SET_SWITCH_POSITION;	/* home where it stands */
		if (h->flags & HOME_USE_INDEX)
			return HOME_INDEX_ONLY_START;
		homing_report("invalid homing config: non-zero LATCH_VEL needs either SEARCH_VEL or USE_INDEX");
		return HOME_ABORT;
	}
	if (h->latch_vel == 0.0) {
		homing_report("invalid homing config: non-zero SEARCH_VEL needs LATCH_VEL");
		return HOME_ABORT;
	}
	return h->home_sw ? HOME_INITIAL_BACKOFF_START : HOME_INITIAL_SEARCH_START;
}

/* After the final move (or instead of it): lock the indexer, or done. */
static int after_final_state(int j)
{
	return (homing_g.h[j].flags & HOME_UNLOCK_FIRST) ? HOME_LOCK : HOME_FINISHED;
}

/* In a *_WAIT state without the awaited event: abort on a limit switch or when the
 * move has ended. Returns true when the joint was sent to ABORT. */
static bool move_failed(int j)
{
	struct homing_priv *h = &homing_g.h[j];
	struct homing_joint *jt = jt_of(j);

	if (!(h->flags & HOME_IGNORE_LIMITS) && (jt->on_pos_limit || jt->on_neg_limit)) {
		homing_report("j%d hit limit in home state %d", j, h->state);
		h->state = HOME_ABORT;
		return true;
	}
	if (!jt->free_tp_active) {
		homing_report("j%d end of move in home state %d", j, h->state);
		h->state = HOME_ABORT;
		return true;
	}
	return false;
}

/* The ABORT actions (motion.md 9.3 step 11): not homed, not homing, index-enable
 * dropped, planner stopped, indexer locked again. */
static void abort_joint(int j)
{
	struct homing_priv *h = &homing_g.h[j];

	h->homing = false;
	h->homed = false;
	h->index_enable = false;
	h->sync_ready = false;
	h->pause_ns = 0;
	if (h->flags & HOME_UNLOCK_FIRST)
		h->unlock = false;
	stop_move(j);
	h->state = HOME_IDLE;
}

/* A synchronized joint (negative sequence) that aborts takes its group with it: the
 * others must not finish a gantry alone. */
static void abort_group_of(int j)
{
	int k, s = homing_seq_abs(j);

	if (homing_g.h[j].sequence >= 0)
		return;
	for (k = 0; k < homing_g.num_joints; k++)
		if (k != j && homing_seq_abs(k) == s && homing_g.h[k].state != HOME_IDLE)
			abort_joint(k);
}

/* Synchronized final move: every joint of j's group that is homing waits at
 * FINAL_MOVE_START with its pause done. */
static bool group_ready(int j)
{
	int k, s = homing_seq_abs(j);

	for (k = 0; k < homing_g.num_joints; k++) {
		struct homing_priv *hk = &homing_g.h[k];

		if (homing_seq_abs(k) != s || hk->state == HOME_IDLE)
			continue;
		if (hk->state != HOME_FINAL_MOVE_START || !hk->sync_ready)
			return false;
	}
	return true;
}

static void start_final_move(int j)
{
	struct homing_priv *h = &homing_g.h[j];
	struct homing_joint *jt = jt_of(j);

	h->sync_ready = false;
	h->state = HOME_FINAL_MOVE_WAIT;
	h->move_started = true;
	if (h->flags & HOME_NO_FINAL_MOVE)
		return;		/* the WAIT state sees the planner stopped and finishes */
	jt->free_pos_cmd = h->home;
	jt->free_vel_lim = h->final_vel > 0.0 ? clamp_speed(j, h->final_vel) : jt->max_vel;
	jt->free_tp_enable = true;
}

/* The edge the latch move waited for: with index, arm it and keep moving. */
static int latch_state(int j)
{
	if (homing_g.h[j].flags & HOME_USE_INDEX)
		return HOME_INDEX_SEARCH_START;
	stop_move(j);
	return HOME_SET_SWITCH_POSITION;
}

/* A *_START state of a search move: once the pause is over, a move at vel toward the
 * far end and state 'wait'; but first the switch must be closed (need 1) or open
 * (need 0), else 'msg' and ABORT (need -1: no check). Returns "run the joint again". */
static bool search_start(int j, long period_ns, double vel, int need, const char *msg, int wait)
{
	struct homing_priv *h = &homing_g.h[j];

	if (!paused_enough(j, period_ns))
		return false;
	if (need >= 0 && h->home_sw != (need == 1)) {
		homing_report("%s", msg);
		h->state = HOME_ABORT;
		return true;
	}
	start_search_move(j, vel);
	h->state = wait;
	return false;
}

/* A *_WAIT state of a search move: 'event' stops the move and ends the state in
 * 'next', or for next = LATCH_EDGE in latch_state()'s (which keeps moving for an
 * index); until then the move must not end or hit a limit (move_failed). */
#define LATCH_EDGE (-1)
static bool search_wait(int j, bool event, int next)
{
	if (!event)
		return move_failed(j);
	if (next == LATCH_EDGE) {
		homing_g.h[j].state = latch_state(j);
	} else {
		stop_move(j);
		homing_g.h[j].state = next;
	}
	return true;
}

static void set_index_position(int j)
{
	struct homing_priv *h = &homing_g.h[j];
	struct homing_joint *jt = jt_of(j);

	if (h->flags & HOME_INDEX_NO_ENCODER_RESET) {
		shift_position(j, h->home_offset - jt->pos_fb);
		return;
	}
	/* the encoder zeroed its count at the index: motor position 0 is HOME_OFFSET */
	jt->motor_offset = -h->home_offset;
	jt->pos_fb = jt->motor_pos_fb - (jt->backlash_filt + jt->motor_offset);
	jt->pos_cmd = jt->pos_fb;
	jt->free_pos = jt->pos_fb;
	jt->free_pos_cmd = jt->pos_fb;
}

/* One joint, one period. */
static void home_one_joint(int j, long period_ns)
{
	struct homing_priv *h = &homing_g.h[j];
	struct homing_joint *jt = jt_of(j);
	bool again;
	int k;

	do {
		again = false;
		switch (h->state) {
		case HOME_IDLE:
			break;
		case HOME_START:
			if ((h->flags & HOME_NO_REHOME) && h->homed) {
				h->state = HOME_IDLE;
				break;
			}
			if ((h->flags & HOME_IS_SHARED) && h->home_sw) {
				homing_report("Cannot home while shared home switch is closed");
				h->homing = false;
				h->state = HOME_IDLE;
				break;
			}
			h->homing = true;
			h->homed = false;
			h->sync_ready = false;
			h->pause_ns = 0;
			stop_move(j);
			h->state = (h->flags & HOME_UNLOCK_FIRST) ? HOME_UNLOCK : first_state(j);
			again = true;
			break;
		case HOME_UNLOCK:
			h->unlock = true;
			h->state = HOME_UNLOCK_WAIT;
			break;
		case HOME_UNLOCK_WAIT:
			if (h->is_unlocked) {
				h->state = first_state(j);
				again = true;
			}
			break;
		case HOME_INITIAL_BACKOFF_START:
			again = search_start(j, period_ns, -h->search_vel, -1, 0,
					     HOME_INITIAL_BACKOFF_WAIT);
			break;
		case HOME_INITIAL_BACKOFF_WAIT:
			again = search_wait(j, !h->home_sw, HOME_INITIAL_SEARCH_START);
			break;
		case HOME_INITIAL_SEARCH_START:
			again = search_start(j, period_ns, h->search_vel, -1, 0,
					     HOME_INITIAL_SEARCH_WAIT);
			break;
		case HOME_INITIAL_SEARCH_WAIT:
			again = search_wait(j, h->home_sw, HOME_SET_COARSE_POSITION);
			break;
		case HOME_SET_COARSE_POSITION:
			shift_position(j, h->home_offset - jt->pos_fb);
			h->state = (h->search_vel > 0.0) == (h->latch_vel > 0.0) ?
				   HOME_FINAL_BACKOFF_START : HOME_FALL_SEARCH_START;
			again = true;
			break;
		case HOME_FINAL_BACKOFF_START:
			again = search_start(j, period_ns, -h->search_vel, 1,
					     "Home switch inactive before start of backoff move",
					     HOME_FINAL_BACKOFF_WAIT);
			break;
		case HOME_FINAL_BACKOFF_WAIT:
			again = search_wait(j, !h->home_sw, HOME_RISE_SEARCH_START);
			break;
		case HOME_RISE_SEARCH_START:
			again = search_start(j, period_ns, h->latch_vel, 0,
					     "Home switch active before start of latch move",
					     HOME_RISE_SEARCH_WAIT);
			break;
		case HOME_RISE_SEARCH_WAIT:
			again = search_wait(j, h->home_sw, LATCH_EDGE);
			break;
		case HOME_FALL_SEARCH_START:
			again = search_start(j, period_ns, h->latch_vel, 1,
					     "Home switch inactive before start of latch move",
					     HOME_FALL_SEARCH_WAIT);
			break;
		case HOME_FALL_SEARCH_WAIT:
			again = search_wait(j, !h->home_sw, LATCH_EDGE);
			break;
		case HOME_SET_SWITCH_POSITION:
			/* an absolute encoder already reads the position: HOME_OFFSET is added */
			shift_position(j, (h->flags & HOME_ABSOLUTE_ENCODER) ?
					  h->home_offset : h->home_offset - jt->pos_fb);
			h->state = ((h->flags & HOME_ABSOLUTE_ENCODER) && (h->flags & HOME_NO_FINAL_MOVE)) ?
				   after_final_state(j) : HOME_FINAL_MOVE_START;
			again = true;
			break;
		case HOME_INDEX_ONLY_START:
			if (!paused_enough(j, period_ns))
				break;
			shift_position(j, h->home_offset - jt->pos_fb);	/* coarse */
			h->state = HOME_INDEX_SEARCH_START;
			again = true;
			break;
		case HOME_INDEX_SEARCH_START:
			h->index_enable = true;
			start_search_move(j, h->latch_vel);
			h->state = HOME_INDEX_SEARCH_WAIT;
			break;
		case HOME_INDEX_SEARCH_WAIT:
			again = search_wait(j, !h->index_enable, HOME_SET_INDEX_POSITION);
			break;
		case HOME_SET_INDEX_POSITION:
			set_index_position(j);
			h->state = HOME_FINAL_MOVE_START;
			again = true;
			break;
		case HOME_FINAL_MOVE_START:
			if (!h->sync_ready) {
				if (!paused_enough(j, period_ns))
					break;
				h->sync_ready = true;
			}
			if (h->sequence >= 0) {
				start_final_move(j);
				break;
			}
			if (!group_ready(j))
				break;
			for (k = 0; k < homing_g.num_joints; k++)	/* the group starts together */
				if (homing_seq_abs(k) == homing_seq_abs(j) &&
				    homing_g.h[k].state == HOME_FINAL_MOVE_START)
					start_final_move(k);
			break;
		case HOME_FINAL_MOVE_WAIT:
			if (h->move_started)
				break;	/* started by a group member this period: planner not run yet */
			if (!(h->flags & HOME_IGNORE_LIMITS) && (jt->on_pos_limit || jt->on_neg_limit)) {
				homing_report("j%d hit limit in home state %d", j, h->state);
				h->state = HOME_ABORT;
				again = true;
				break;
			}
			if (!jt->free_tp_active) {
				stop_move(j);
				h->state = after_final_state(j);
				again = true;
			}
			break;
		case HOME_LOCK:
			h->unlock = false;
			h->state = HOME_LOCK_WAIT;
			break;
		case HOME_LOCK_WAIT:
			if (!h->is_unlocked) {
				h->state = HOME_FINISHED;
				again = true;
			}
			break;
		case HOME_FINISHED:
			h->homing = false;
			h->homed = true;
			jt->free_pos_cmd = jt->free_pos;	/* the planner rests where it is */
			h->state = HOME_IDLE;
			break;
		case HOME_ABORT:
		default:
			abort_joint(j);
			abort_group_of(j);
			break;
		}
	} while (again);
}

/* --- Home-All and sequences --- */

/* Joints taking part in the running Home-All (or in the one synchronized group). */
static bool seq_member(int j)
{
	if (!homing_g.joints[j].active)
		return false;
	if (homing_g.seq_home_all && homing_seq_abs(j) > HOME_SEQUENCE_MAX)
		return false;
	return homing_seq_abs(j) == homing_g.seq_current;
}

static void sequence_step(void)
{
	int j;
	bool found, busy, failed;

	for (;;) {
		switch (homing_g.seq_state) {
		case HOME_SEQ_START_JOINTS:
			found = false;
			for (j = 0; j < homing_g.num_joints; j++) {
				if (!seq_member(j))
					continue;
				found = true;
				if (!(homing_g.seq_skip & (1u << j)))
					homing_g.h[j].state = HOME_START;
			}
			if (found) {
				homing_g.seq_state = HOME_SEQ_WAIT_JOINTS;
				return;
			}
			/* no joint in this sequence: Home-All ends, but may start at 0 or 1 */
			if (homing_g.seq_home_all && homing_g.seq_current == 0) {
				homing_g.seq_current = 1;
				continue;
			}
			homing_g.seq_state = HOME_SEQ_IDLE;
			return;
		case HOME_SEQ_WAIT_JOINTS:
			busy = failed = false;
			for (j = 0; j < homing_g.num_joints; j++) {
				if (!seq_member(j))
					continue;
				if (homing_g.h[j].state != HOME_IDLE)
					busy = true;
				else if (!homing_g.h[j].homed)
					failed = true;
			}
			if (busy)
				return;
			if (failed || !homing_g.seq_home_all) {
				homing_g.seq_state = HOME_SEQ_IDLE;
				return;
			}
			homing_g.seq_current++;
			homing_g.seq_state = HOME_SEQ_START_JOINTS;
			continue;
		default:
			return;
		}
	}
}

bool do_homing(long period_ns)
{
	bool was_allhomed = get_allhomed();
	int j;

	for (j = 0; j < homing_g.num_joints; j++)
		homing_g.h[j].move_started = false;
	sequence_step();
	for (j = 0; j < homing_g.num_joints; j++) {
		if (homing_g.joints[j].active) {
			home_one_joint(j, period_ns);
		} else if (homing_g.h[j].state != HOME_IDLE || homing_g.h[j].homing) {
			abort_joint(j);		/* deactivated while homing */
			abort_group_of(j);
		}
	}
	return !was_allhomed && get_allhomed();
}

/* --- commands --- */

int do_home_joint(int jno)
{
	int j, todo = 0;

	if (jno == -1 || (jno >= 0 && jno < homing_g.num_joints && homing_g.h[jno].sequence < 0)) {
		bool all = jno == -1;
		int seq = all ? 0 : homing_seq_abs(jno);

		if (!all && !homing_g.joints[jno].active)
			return -EINVAL;
		if (homing_g.seq_state != HOME_SEQ_IDLE)
			return -EBUSY;
		for (j = 0; j < homing_g.num_joints; j++) {
			int s = homing_seq_abs(j);

			if (!homing_g.joints[j].active || s > HOME_SEQUENCE_MAX || (!all && s != seq))
				continue;
			if (homing_g.h[j].state != HOME_IDLE && homing_g.h[j].state != HOME_START)
				return -EBUSY;	/* already homing: the request is dropped */
		}
		homing_g.seq_skip = 0;
		for (j = 0; j < homing_g.num_joints; j++) {
			int s = homing_seq_abs(j);

			if (!homing_g.joints[j].active || s > HOME_SEQUENCE_MAX || (!all && s != seq))
				continue;
			if ((homing_g.h[j].flags & HOME_NO_REHOME) && homing_g.h[j].homed) {
				homing_g.seq_skip |= 1u << j;
			} else {
				homing_g.h[j].homed = false;
				todo++;
			}
		}
		if (!todo)
			return 1;
		homing_g.seq_home_all = all;
		homing_g.seq_current = seq;
		homing_g.seq_state = HOME_SEQ_START_JOINTS;
		return 0;
	}
	if (jno < 0 || jno >= homing_g.num_joints || !homing_g.joints[jno].active)
		return -EINVAL;
	if (homing_g.seq_state != HOME_SEQ_IDLE || homing_g.h[jno].state != HOME_IDLE)
		return -EBUSY;
	if ((homing_g.h[jno].flags & HOME_NO_REHOME) && homing_g.h[jno].homed)
		return 1;
	homing_g.h[jno].state = HOME_START;
	return 0;
}

void do_cancel_homing(int jno)
{
	int j;

	if (jno < -1 || jno >= homing_g.num_joints)
		return;
	homing_g.seq_state = HOME_SEQ_IDLE;
	for (j = 0; j < homing_g.num_joints; j++) {
		struct homing_priv *h = &homing_g.h[j];

		if (jno >= 0 && j != jno)
			continue;
		if (h->state != HOME_IDLE || h->homing) {
			abort_joint(j);
			abort_group_of(j);
		}
	}
}

int set_unhomed(int jno, int motion_state)
{
	bool disabled = motion_state == HOMING_MOTION_DISABLED;
	int j;

	if (jno < -2 || jno >= homing_g.num_joints)
		return -EINVAL;
	if (get_homing_is_active()) {
		homing_report("Cannot unhome while homing, joint %d", jno);
		return -EBUSY;
	}
	if (jno >= 0) {
		if (is_extra(jno) && !disabled) {
			homing_report("Cannot unhome extra joint %d unless motion is disabled", jno);
			return -EBUSY;
		}
		if (!disabled && homing_g.joints[jno].free_tp_active) {
			homing_report("Cannot unhome while moving, joint %d", jno);
			return -EBUSY;
		}
		homing_g.h[jno].homed = false;
		return 0;
	}
	/* all (-1) or volatile (-2): check every one first, then unhome */
	for (j = 0; j < homing_g.num_joints; j++) {
		if (!homing_g.joints[j].active || (jno == -2 && !homing_g.h[j].volatile_home) ||
		    (is_extra(j) && !disabled))
			continue;
		if (!disabled && homing_g.joints[j].free_tp_active) {
			homing_report("Cannot unhome while moving, joint %d", j);
			return -EBUSY;
		}
	}
	for (j = 0; j < homing_g.num_joints; j++) {
		if (!homing_g.joints[j].active || (jno == -2 && !homing_g.h[j].volatile_home) ||
		    (is_extra(j) && !disabled))
			continue;
		homing_g.h[j].homed = false;
	}
	return 0;
}

int do_unhome_joint(int jno)
{
	return set_unhomed(jno, HOMING_MOTION_FREE);
}

bool homing_probe_trip(bool no_probe_home_error)
{
	if (no_probe_home_error || !get_homing_is_active())
		return false;
	do_cancel_homing(-1);
	homing_report("Probe tripped during homing motion.");
	return true;
}

/* --- parameters --- */

/* A group with one negative member is synchronized: every member negative. */
static void normalise_sequences(void)
{
	int j, k;

	for (j = 0; j < homing_g.num_joints; j++)
		homing_g.h[j].sequence = homing_g.h[j].sequence_raw;
	for (j = 0; j < homing_g.num_joints; j++) {
		if (homing_g.h[j].sequence_raw >= 0)
			continue;
		for (k = 0; k < homing_g.num_joints; k++)
			if (homing_seq_abs(k) == -homing_g.h[j].sequence_raw)
				homing_g.h[k].sequence = -homing_seq_abs(k);
	}
}

void set_joint_homing_params(int jno, double home_offset, double home, double home_final_vel,
			     double home_search_vel, double home_latch_vel, int home_flags,
			     int home_sequence, bool volatile_home)
{
	struct homing_priv *h;

	if (jno < 0 || jno >= homing_g.num_joints || homing_g.h[jno].state != HOME_IDLE)
		return;
	h = &homing_g.h[jno];
	h->home_offset = home_offset;
	h->home = home;
	h->final_vel = home_final_vel;
	h->search_vel = home_search_vel;
	h->latch_vel = home_latch_vel;
	h->flags = home_flags;
	h->sequence_raw = home_sequence;
	h->volatile_home = volatile_home;
	normalise_sequences();
}

void update_joint_homing_params(int jno, double home_offset, double home, int home_sequence)
{
	struct homing_priv *h;

	if (jno < 0 || jno >= homing_g.num_joints || homing_g.h[jno].state != HOME_IDLE)
		return;
	h = &homing_g.h[jno];
	h->home_offset = home_offset;
	h->home = home;
	h->sequence_raw = home_sequence;
	normalise_sequences();
}
