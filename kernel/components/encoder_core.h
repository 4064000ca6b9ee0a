/* SPDX-License-Identifier: GPL-2.0-or-later */
/* encoder_core.h - software encoder counting, encoder(9) and the Encoder section
 * of the realtime components chapter; HAL-free so unit tests drive it directly.
 * Two halves that may run in different threads:
 *  - enc_update() (update-counters, fast thread, no FP) samples A/B/Z and the
 *    latch input, counts (x4 quadrature, x1 quadrature, or counter mode with an
 *    optional missing-tooth index), timestamps each count change with its own
 *    clock (the sum of its periods: deterministic, no wall clock) and records
 *    index and latch events;
 *  - enc_capture() (capture-position, slower thread, FP) applies reset and the
 *    index-enable handshake, scales, latches, and estimates velocity.
 * What update hands to capture is one struct behind a sequence lock. */
#ifndef ENCODER_CORE_H
#define ENCODER_CORE_H

#include "rtapi.h"

/* Quadrature position of the A/B levels: one step per edge, A leading B when
 * counting up (00 -> 10 -> 11 -> 01 -> 00), as sim_encoder(9) makes them. */
static inline rtapi_u8 enc_quad_pos(bool a, bool b)
{
	return a ? (b ? 2 : 1) : (b ? 3 : 0);
}

/* Count change from quadrature position old to cur. x4 counts every edge; x1
 * counts once per cycle, on A rising while B is low (and -1 on A falling while
 * B is low), so chatter on that one edge cannot drift. A jump of two positions
 * (an edge was missed: the direction is unknown) counts nothing. */
static inline int enc_quad_delta(rtapi_u8 old, rtapi_u8 cur, bool x4)
{
	rtapi_u8 d = (rtapi_u8)((cur - old) & 3);

	if (!x4)
		return (old == 0 && cur == 1) ? 1 : (old == 1 && cur == 0) ? -1 : 0;
	return d == 1 ? 1 : d == 3 ? -1 : 0;
}

/* Written by enc_update() only (inside the sequence lock), read by enc_capture(). */
struct enc_shared {
	rtapi_u32 seq;		/* odd while enc_update() is writing */
	rtapi_s32 raw;		/* counts since load: the rawcounts pin */
	rtapi_u64 now_ns;	/* update's clock: the sum of its periods */
	rtapi_u64 edge_ns;	/* update's clock at the latest count change */
	rtapi_s32 index_raw;	/* raw at the index event numbered index_gen */
	rtapi_s32 latch_raw;	/* raw at the latch event numbered latch_gen */
	rtapi_u32 index_gen, latch_gen;
};

/* Written by enc_capture() only, read by enc_update(): which events it has taken.
 * update records a new event only when the previous one was taken, so the first
 * index pulse after index-enable is the one that resets the counts. */
struct enc_acks {
	rtapi_u32 index_ack, latch_ack;
};

struct enc_update_in {		/* pins sampled by update-counters */
	bool a, b, z, index_enable, latch_input, latch_rising, latch_falling;
	bool counter_mode, x4_mode;
	rtapi_s32 missing_teeth;	/* counter mode: teeth missing at the index gap */
};

struct enc_update_state {	/* private to enc_update() */
	bool primed;		/* false until the first sample: no previous levels */
	rtapi_u8 pos;		/* quadrature position of the last sample */
	bool a, z, latch;	/* last levels */
	rtapi_u8 teeth_seen;	/* missing teeth: A edges seen so far, up to 2 */
	rtapi_u64 tooth_ns;	/* missing teeth: clock at the last A rising edge */
	rtapi_u64 tooth_interval_ns;	/* missing teeth: the last normal tooth interval */
};

/* Counter mode: one count per A rising edge; with missing_teeth > 0 an interval
 * longer than halfway between one tooth and the gap (1 + missing teeth) is the
 * gap: it adds the missing teeth and is an index event. */
static inline int enc_counter_edge(struct enc_update_state *u, rtapi_s32 missing, rtapi_u64 now,
				   bool *gap)
{
	rtapi_u64 interval = now - u->tooth_ns;

	u->tooth_ns = now;
	if (missing <= 0)
		return 1;
	if (u->teeth_seen >= 2 && 2 * interval > (rtapi_u64)(missing + 2) * u->tooth_interval_ns) {
		*gap = true;
		return 1 + missing;
	}
	if (u->teeth_seen >= 1)
		u->tooth_interval_ns = interval;
	if (u->teeth_seen < 2)
		u->teeth_seen++;
	return 1;
}

/* One sample of update-counters. Realtime, no FP. Returns the new raw count. */
static inline rtapi_s32 enc_update(struct enc_update_state *u, struct enc_shared *sh,
				   const struct enc_acks *acks, const struct enc_update_in *in,
				   long period_ns)
{
	rtapi_u64 now = sh->now_ns + (rtapi_u64)(period_ns > 0 ? period_ns : 0);
	rtapi_u8 pos = enc_quad_pos(in->a, in->b);
	bool gap = false, index_event, latch_event;
	int delta = 0;
	rtapi_u32 seq;

	if (!u->primed) {	/* the levels at load time are not edges */
		u->primed = true;
		u->pos = pos;
		u->a = in->a;
		u->z = in->z;
		u->latch = in->latch_input;
	}
	if (in->counter_mode) {
		if (in->a && !u->a)
			delta = enc_counter_edge(u, in->missing_teeth, now, &gap);
	} else {
		delta = enc_quad_delta(u->pos, pos, in->x4_mode);
	}
	index_event = in->index_enable && ((in->z && !u->z) || gap) &&
		      sh->index_gen == __atomic_load_n(&acks->index_ack, __ATOMIC_ACQUIRE);
	latch_event = in->latch_input != u->latch &&
		      (in->latch_input ? in->latch_rising : in->latch_falling) &&
		      sh->latch_gen == __atomic_load_n(&acks->latch_ack, __ATOMIC_ACQUIRE);
	u->pos = pos;
	u->a = in->a;
	u->z = in->z;
	u->latch = in->latch_input;

	seq = sh->seq;
	__atomic_store_n(&sh->seq, seq + 1, __ATOMIC_RELAXED);
	__atomic_thread_fence(__ATOMIC_RELEASE);
	sh->now_ns = now;
	if (delta) {
		sh->raw = (rtapi_s32)((rtapi_u32)sh->raw + (rtapi_u32)delta);	/* wraps */
		sh->edge_ns = now;
	}
	if (index_event) {
		sh->index_raw = sh->raw;
		sh->index_gen++;
	}
	if (latch_event) {
		sh->latch_raw = sh->raw;
		sh->latch_gen++;
	}
	__atomic_store_n(&sh->seq, seq + 2, __ATOMIC_RELEASE);
	return sh->raw;
}

/* A consistent copy of what update wrote. Update runs in a faster thread; if it
 * keeps interrupting the copy, the last attempt is used (it can only be off by
 * the one sample being written). Realtime. */
static inline void enc_shared_read(const struct enc_shared *sh, struct enc_shared *copy)
{
	rtapi_u32 s1, s2;
	int tries;

	for (tries = 0; tries < 8; tries++) {
		s1 = __atomic_load_n(&sh->seq, __ATOMIC_ACQUIRE);
		copy->raw = sh->raw;
		copy->now_ns = sh->now_ns;
		copy->edge_ns = sh->edge_ns;
		copy->index_raw = sh->index_raw;
		copy->latch_raw = sh->latch_raw;
		copy->index_gen = sh->index_gen;
		copy->latch_gen = sh->latch_gen;
		__atomic_thread_fence(__ATOMIC_ACQUIRE);
		s2 = __atomic_load_n(&sh->seq, __ATOMIC_RELAXED);
		if (s1 == s2 && !(s1 & 1))
			break;
	}
	copy->seq = s2;
}

struct enc_capture_in {		/* pins read by capture-position */
	bool reset, index_enable;
	double scale;		/* counts per unit; |scale| < 1e-20 is taken as 1 */
	double min_speed;	/* units per second */
};

struct enc_capture_out {	/* pins written by capture-position */
	rtapi_s32 counts, counts_latched;
	double position, position_interpolated, velocity, position_latched;
	bool clear_index_enable;	/* the index reset happened: set index-enable FALSE */
};

struct enc_capture_state {	/* private to enc_capture() */
	rtapi_s32 offset;	/* raw count that reads as 0 counts */
	rtapi_s32 prev_raw;	/* raw at the previous capture that saw a change */
	rtapi_u64 prev_edge_ns;	/* update's clock at that change */
	double vel_counts;	/* counts per second */
	rtapi_s32 counts_latched;
};

/* Velocity in counts/s: the counts between the latest change seen by the previous
 * capture and the latest change now, divided by the time between those two
 * changes (no quantization noise: both ends are edges). Without a change, the
 * true speed is below one count per time since the last change, so the estimate
 * decays as that bound; enc_capture() outputs 0 once it is below min-speed. */
static inline void enc_velocity(struct enc_capture_state *c, const struct enc_shared *snap)
{
	rtapi_u64 dt;
	double bound;

	if (snap->raw != c->prev_raw) {
		dt = snap->edge_ns - c->prev_edge_ns;
		if (dt > 0)
			c->vel_counts = (double)(rtapi_s32)((rtapi_u32)snap->raw -
							     (rtapi_u32)c->prev_raw) * 1e9 / (double)dt;
		c->prev_raw = snap->raw;
		c->prev_edge_ns = snap->edge_ns;
		return;
	}
	dt = snap->now_ns - c->prev_edge_ns;
	if (dt == 0)
		return;
	bound = 1e9 / (double)dt;
	if (c->vel_counts > bound)
		c->vel_counts = bound;
	else if (c->vel_counts < -bound)
		c->vel_counts = -bound;
}

/* One capture-position. Realtime, uses FP. */
static inline void enc_capture(struct enc_capture_state *c, const struct enc_shared *snap,
			       struct enc_acks *acks, const struct enc_capture_in *in,
			       struct enc_capture_out *o)
{
	double scale = in->scale;
	double interp, vel;

	if (scale < 1e-20 && scale > -1e-20)
		scale = 1.0;
	o->clear_index_enable = false;
	if (snap->index_gen != acks->index_ack) {
		if (in->index_enable) {	/* else the request was withdrawn meanwhile */
			c->offset = snap->index_raw;
			o->clear_index_enable = true;
		}
		__atomic_store_n(&acks->index_ack, snap->index_gen, __ATOMIC_RELEASE);
	}
	if (in->reset)
		c->offset = snap->raw;
	if (snap->latch_gen != acks->latch_ack) {
		c->counts_latched = (rtapi_s32)((rtapi_u32)snap->latch_raw - (rtapi_u32)c->offset);
		__atomic_store_n(&acks->latch_ack, snap->latch_gen, __ATOMIC_RELEASE);
	}
	enc_velocity(c, snap);

	o->counts = (rtapi_s32)((rtapi_u32)snap->raw - (rtapi_u32)c->offset);
	o->position = o->counts / scale;
	o->counts_latched = c->counts_latched;
	o->position_latched = c->counts_latched / scale;
	vel = c->vel_counts / scale;
	if (vel < in->min_speed && vel > -in->min_speed)
		vel = 0.0;
	o->velocity = vel;
	/* Between counts, move on at the measured speed, by at most one count. */
	interp = 0.0;
	if (vel != 0.0) {
		interp = c->vel_counts * (double)(snap->now_ns - snap->edge_ns) * 1e-9;
		if (interp > 1.0)
			interp = 1.0;
		else if (interp < -1.0)
			interp = -1.0;
	}
	o->position_interpolated = (o->counts + interp) / scale;
}

#endif /* ENCODER_CORE_H */
