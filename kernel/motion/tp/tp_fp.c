/* tp_fp.c - planner set-up, configuration, status and execution control
 * (pause/resume/step/abort/clear).  Queueing is in tp_add_fp.c, the cycle in
 * tp_run_fp.c.  FP unit: every function may touch doubles. */
#include "tp_internal.h"
#include "rtapi_math.h"
#include "rtapi_string.h"

static int bad(double v)
{
	return !rtapi_isfinite(v);
}

unsigned long tp_size(int queue_size)
{
	if (queue_size < TP_MIN_QUEUE_SIZE || queue_size > TP_MAX_QUEUE_SIZE)
		return 0;
	return (unsigned long)sizeof(struct tp) + (unsigned long)queue_size * sizeof(struct tc);
}

struct tp *tp_init(void *mem, unsigned long bytes, int queue_size)
{
	unsigned long need = tp_size(queue_size);
	if (!mem || need == 0 || bytes < need)
		return 0;
	struct tp *tp = mem;
	memset(tp, 0, need);
	tp->size = queue_size;
	tp->cycle = 0.001;
	tp->vmax = tp->ini_maxvel = TP_BIG;
	tp->vlimit = TP_BIG;
	tp->amax = TP_BIG;
	tp->term_cond = TP_TERM_STOP;
	tp->max_feed_scale = 1.0;
	for (int i = 0; i < TP_N; i++) {
		tp->axis_vmax[i] = TP_BIG;
		tp->axis_amax[i] = TP_BIG;
	}
	tp->arc_blend = 1;
	tp->arc_fallback = 1;
	tp->opt_depth = TP_DEFAULT_OPT_DEPTH;
	tp->gap_cycles = 4;
	tp->ramp_freq = 100;
	tp->kink_ratio = 0.1;
	tp->spindle_scale_out = 1.0;
	return tp;
}

const char *tp_strerror(int err)
{
	switch (err) {
	case TP_OK: return "ok";
	case TP_ERR_INVALID: return "invalid argument";
	case TP_ERR_QUEUE_FULL: return "motion queue full";
	case TP_ERR_NO_MEMORY: return "planner memory too small";
	case TP_ERR_BUSY: return "planner busy (moving)";
	case TP_ERR_ABORTING: return "planner aborting";
	case TP_ERR_ZERO_LENGTH: return "zero-length move";
	case TP_ERR_NO_SYNC: return "rigid tap needs spindle synchronisation (units per rev)";
	default: return "unknown planner error";
	}
}

struct tc *tp_seg(struct tp *tp, int i)
{
	return &tp->q[(tp->head + i) % tp->size];
}

const struct tc *tp_seg_c(const struct tp *tp, int i)
{
	return &tp->q[(tp->head + i) % tp->size];
}

int tp_set_cycle_time(struct tp *tp, double secs)
{
	if (bad(secs) || secs <= 0 || secs > 1.0)
		return TP_ERR_INVALID;
	tp->cycle = secs;
	return 0;
}

int tp_set_vmax(struct tp *tp, double vmax, double ini_maxvel)
{
	if (bad(vmax) || bad(ini_maxvel) || vmax <= 0 || ini_maxvel <= 0)
		return TP_ERR_INVALID;
	tp->vmax = vmax;
	tp->ini_maxvel = ini_maxvel;
	return 0;
}

int tp_set_vlimit(struct tp *tp, double vlimit)
{
	if (bad(vlimit) || vlimit < 0)
		return TP_ERR_INVALID;
	tp->vlimit = vlimit;
	return 0;
}

int tp_set_amax(struct tp *tp, double amax)
{
	if (bad(amax) || amax <= 0)
		return TP_ERR_INVALID;
	tp->amax = amax;
	return 0;
}

int tp_set_term_cond(struct tp *tp, int cond, double tolerance)
{
	if (cond < TP_TERM_STOP || cond > TP_TERM_PARABOLIC || bad(tolerance) || tolerance < 0)
		return TP_ERR_INVALID;
	tp->term_cond = cond;
	tp->tolerance = tolerance;
	return 0;
}

int tp_set_max_feed_scale(struct tp *tp, double scale)
{
	if (bad(scale) || scale < 1.0)	/* planning at less than 100 % would break override 1 */
		return TP_ERR_INVALID;
	tp->max_feed_scale = scale;
	return 0;
}

int tp_set_axis_limits(struct tp *tp, int axis, double vmax, double amax)
{
	if (axis < 0 || axis >= TP_N || bad(vmax) || bad(amax) || vmax <= 0 || amax <= 0)
		return TP_ERR_INVALID;
	tp->axis_vmax[axis] = vmax;
	tp->axis_amax[axis] = amax;
	return 0;
}

int tp_set_arc_blend(struct tp *tp, int enable, int fallback_enable, int opt_depth,
		     int gap_cycles, double ramp_freq, double kink_ratio)
{
	if (opt_depth < 0 || opt_depth > 10000 || gap_cycles < 0 || bad(ramp_freq) || ramp_freq < 0
	    || bad(kink_ratio) || kink_ratio < 0 || kink_ratio > 1)
		return TP_ERR_INVALID;
	tp->arc_blend = !!enable;
	tp->arc_fallback = !!fallback_enable;
	tp->opt_depth = opt_depth;
	tp->gap_cycles = gap_cycles;
	tp->ramp_freq = ramp_freq;
	tp->kink_ratio = kink_ratio;
	return 0;
}

int tp_set_pos(struct tp *tp, const struct tp_pose *pos)
{
	double v[TP_N];
	if (!pos)
		return TP_ERR_INVALID;
	pose_to_vec(pos, v);
	for (int i = 0; i < TP_N; i++)
		if (bad(v[i]))
			return TP_ERR_INVALID;
	if (tp->count > 0)
		return TP_ERR_BUSY;
	for (int i = 0; i < TP_N; i++)
		tp->pos[i] = tp->goal[i] = v[i];
	tp->cur_vel = 0;
	return 0;
}

int tp_get_pos(const struct tp *tp, struct tp_pose *pos)
{
	if (!pos)
		return TP_ERR_INVALID;
	vec_to_pose(tp->pos, pos);
	return 0;
}

static rtapi_u64 set_bit(rtapi_u64 word, rtapi_u64 bit, int on)
{
	return on ? word | bit : word & ~bit;
}

int tp_set_dout(struct tp *tp, int index, int start_value, int end_value)
{
	if (index < 0 || index >= TP_MAX_DIO)
		return TP_ERR_INVALID;
	rtapi_u64 bit = (rtapi_u64)1 << index;
	tp->dout_mask |= bit;
	tp->dout_value = set_bit(tp->dout_value, bit, start_value);
	/* only a change at the end is applied there: an immediate change made while the
	 * segment runs is not undone by repeating the start value */
	tp->dout_end_mask = set_bit(tp->dout_end_mask, bit, !start_value != !end_value);
	tp->dout_end_value = set_bit(tp->dout_end_value, bit, end_value);
	return 0;
}

int tp_set_aout(struct tp *tp, int index, double start_value, double end_value)
{
	int i;

	if (index < 0 || index >= TP_MAX_AIO || bad(start_value) || bad(end_value))
		return TP_ERR_INVALID;
	for (i = 0; i < tp->aout_count; i++)
		if (tp->aout[i].index == index)
			break;
	if (i == tp->aout_count) {
		if (tp->aout_count >= TP_SEG_AIO_MAX)
			return TP_ERR_INVALID;
		tp->aout_count++;
	}
	tp->aout[i].index = index;
	tp->aout[i].value = start_value;
	tp->aout[i].has_end = end_value != start_value;
	tp->aout[i].end = end_value;
	return 0;
}

int tp_set_spindle_sync(struct tp *tp, int spindle_num, double units_per_rev, int velocity_mode)
{
	if (spindle_num < 0 || bad(units_per_rev))
		return TP_ERR_INVALID;
	tp->spindle_num = spindle_num;
	tp->uu_per_rev = units_per_rev;
	if (units_per_rev == 0)
		tp->sync_mode = TP_SYNC_NONE;
	else
		tp->sync_mode = velocity_mode ? TP_SYNC_VELOCITY : TP_SYNC_POSITION;
	return 0;
}

int tp_pause(struct tp *tp)
{
	tp->pausing = 1;
	return 0;
}

int tp_resume(struct tp *tp)
{
	tp->pausing = 0;
	tp->stepping = 0;
	tp->step_armed = 0;
	return 0;
}

int tp_step(struct tp *tp)
{
	if (tp->cur_vel != 0)
		return TP_ERR_BUSY;
	tp->stepping = 1;
	tp->step_armed = 0;	/* tp_run_cycle arms it on the segment it starts/continues */
	tp->pausing = 0;
	return 0;
}

int tp_abort(struct tp *tp)
{
	if (tp->count == 0 && tp->cur_vel == 0) {
		tp_clear(tp);
		return 0;
	}
	tp->aborting = 1;
	return 0;
}

int tp_clear(struct tp *tp)
{
	tp->head = 0;
	tp->count = 0;
	tp->aborting = 0;
	tp->pausing = 0;
	tp->stepping = 0;
	tp->step_armed = 0;
	tp->cur_vel = 0;
	tp->sync_state = 0;
	tp->index_requested = tp->index_seen = 0;
	tp->spindle_scale_out = 1.0;
	tp->exec_id = tp->exec_tag = tp->exec_type = 0;
	tp->exec_enables = 0;
	tp->last_motion_type = 0;
	tp->last_sync = TP_SYNC_NONE;
	for (int i = 0; i < TP_N; i++)
		tp->goal[i] = tp->pos[i];
	return 0;
}

int tp_is_done(const struct tp *tp)
{
	return tp->count == 0;
}

int tp_queue_depth(const struct tp *tp)
{
	return tp->count;
}

int tp_active_depth(const struct tp *tp)
{
	int n = 0;
	for (int i = 0; i < tp->count && i < 2; i++)
		if (tp_seg_c(tp, i)->active)
			n++;
	return n;
}

int tp_is_queue_full(const struct tp *tp)
{
	return tp->size - tp->count < TP_ADD_MARGIN;
}

int tp_is_paused(const struct tp *tp)
{
	return tp->pausing && tp->cur_vel == 0;
}

int tp_exec_id(const struct tp *tp)
{
	return tp->exec_id;
}

int tp_segment_info(const struct tp *tp, int n, double *progress, double *vel, double *acc)
{
	const struct tc *tc;

	if (n < 0 || n >= tp->count)
		return TP_ERR_INVALID;
	tc = tp_seg_c(tp, n);
	*progress = tc->progress;
	*vel = tc->vel;
	*acc = tc->acc;
	return 0;
}
