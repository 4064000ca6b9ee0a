/* SPDX-License-Identifier: GPL-2.0-or-later */
/* coord_fp.c - coordinated motion (COORD) on the trajectory planner of tp/tp.h and
 * the per-joint cubic interpolators of tp/cubic.h (motion.md 3, 10): the planner runs
 * once per trajectory period (traj_period_nsec / servo period servo periods), its
 * world position goes through the inverse kinematics into the interpolators, and
 * every servo period each joint takes its interpolated command. The planner's memory
 * is a static buffer: nothing is allocated after load. */
#include "coord.h"
#include "tp/tp.h"
#include "tp/cubic.h"
#include "rtapi_math.h"

#define COORD_QUEUE_SIZE TP_DEFAULT_QUEUE_SIZE
#define COORD_MEM_BYTES (8ul << 20)	/* room for the queue (checked with tp_size) */

struct mot_coord {
	struct tp *tp;
	struct tp_outputs out;		/* of the last planner cycle */
	struct cubic cubic[MOTION_MAX_JOINTS];
	int sync_spindle;
	int queue_size;
	bool filled;			/* the interpolators hold the planner's position */
};

static struct mot_coord coord_state;
static rtapi_u64 coord_mem[COORD_MEM_BYTES / sizeof(rtapi_u64)];

static void to_tp(const EmcPose *p, struct tp_pose *t)
{
	t->x = p->tran.x;
	t->y = p->tran.y;
	t->z = p->tran.z;
	t->a = p->a;
	t->b = p->b;
	t->c = p->c;
	t->u = p->u;
	t->v = p->v;
	t->w = p->w;
}

static void from_tp(const struct tp_pose *t, EmcPose *p)
{
	p->tran.x = t->x;
	p->tran.y = t->y;
	p->tran.z = t->z;
	p->a = t->a;
	p->b = t->b;
	p->c = t->c;
	p->u = t->u;
	p->v = t->v;
	p->w = t->w;
}

static void cmd_to_tp(const struct motion_command *c, struct tp_pose *t)
{
	t->x = c->pos.v[0];
	t->y = c->pos.v[1];
	t->z = c->pos.v[2];
	t->a = c->pos.v[3];
	t->b = c->pos.v[4];
	t->c = c->pos.v[5];
	t->u = c->pos.v[6];
	t->v = c->pos.v[7];
	t->w = c->pos.v[8];
}

int coord_init_values(struct motmod *m)
{
	struct mot_coord *c = &coord_state;
	int q = COORD_QUEUE_SIZE, j;

	while (q > TP_MIN_QUEUE_SIZE && (tp_size(q) == 0 || tp_size(q) > sizeof(coord_mem)))
		q /= 2;
	c->tp = tp_init(coord_mem, sizeof(coord_mem), q);
	if (!c->tp)
		return -ENOMEM;
	c->queue_size = q;
	m->coord_tp = c;
	tp_set_cycle_time(c->tp, m->traj_period_ns * 1e-9);
	for (j = 0; j < MOTION_MAX_JOINTS; j++)
		cubic_init(&c->cubic[j], m->traj_period_ns * 1e-9, m->servo_period_ns * 1e-9);
	coord_set_limits(m);
	return 0;
}

int coord_queue_size(struct motmod *m)
{
	return m->coord_tp->queue_size;
}

void coord_set_position(struct motmod *m, const EmcPose *pos)
{
	struct mot_coord *c = m->coord_tp;
	struct tp_pose t;
	int j;

	tp_clear(c->tp);
	to_tp(pos, &t);
	tp_set_pos(c->tp, &t);
	for (j = 0; j < MOTION_MAX_JOINTS; j++)
		cubic_drain(&c->cubic[j]);
	c->filled = false;
	memset(&c->out, 0, sizeof(c->out));
	c->out.pos = t;
	c->out.done = 1;
}

void coord_abort(struct motmod *m)
{
	tp_abort(m->coord_tp->tp);
	m->probing = false;
}

void coord_clear(struct motmod *m)
{
	tp_clear(m->coord_tp->tp);
	m->probing = false;
}

void coord_pause(struct motmod *m)
{
	tp_pause(m->coord_tp->tp);
}

void coord_resume(struct motmod *m)
{
	tp_resume(m->coord_tp->tp);
}

int coord_step(struct motmod *m)
{
	return tp_step(m->coord_tp->tp) == TP_ERR_BUSY ? -EBUSY : 0;
}

void coord_set_term_cond(struct motmod *m, int cond, double tolerance)
{
	tp_set_term_cond(m->coord_tp->tp, cond, tolerance);
}

int coord_set_arc_blend(struct motmod *m, const struct motion_command *c)
{
	if (!m->coord_tp)
		return -EINVAL;
	if (!(c->value >= 0.0 && c->value <= 1000.0))
		return -EINVAL;
	return tp_set_arc_blend(m->coord_tp->tp, c->mode, c->flags, c->count, (int)(c->value + 0.5), c->scale,
				c->tolerance) ? -EINVAL : 0;
}

void coord_set_limits(struct motmod *m)
{
	struct mot_coord *c = m->coord_tp;
	int l;

	if (!c)
		return;
	tp_set_vmax(c->tp, m->traj_vel, m->traj_vel);
	tp_set_vlimit(c->tp, m->traj_vel_limit);
	tp_set_amax(c->tp, m->traj_acc);
	tp_set_max_feed_scale(c->tp, m->max_feed_scale);
	for (l = 0; l < MOTION_MAX_AXES; l++)
		tp_set_axis_limits(c->tp, l, m->axis[l].vel_limit, m->axis[l].acc_limit);
}

void coord_set_spindlesync(struct motmod *m, int spindle, double units_per_rev, bool velocity_mode)
{
	struct mot_coord *c = m->coord_tp;

	c->sync_spindle = spindle >= 0 && spindle < m->num_spindles ? spindle : 0;
	tp_set_spindle_sync(c->tp, c->sync_spindle, units_per_rev, velocity_mode);
}

static void fill_move(struct motmod *m, const struct motion_command *c, struct tp_move *mv)
{
	memset(mv, 0, sizeof(*mv));
	mv->motion_type = c->motion_type;
	mv->vel = c->vel;
	mv->ini_maxvel = c->ini_maxvel;
	mv->acc = c->acc;
	mv->id = c->id;
	mv->tag = 0;
	mv->enables = (unsigned char)m->enables_new;
	mv->atspeed = c->wait_for_at_speed;
	/* the first feed move after a spindle start that waits (motion.md 14.6) */
	if (m->atspeed_next_feed && (c->motion_type == MOTION_TYPE_FEED ||
				     c->motion_type == MOTION_TYPE_ARC ||
				     c->motion_type == MOTION_TYPE_PROBING)) {
		mv->atspeed = 1;
		m->atspeed_next_feed = false;
	}
	mv->probe_type = c->probe_type;
}

static int tp_result(int r)
{
	return r == TP_ERR_QUEUE_FULL ? -ENOSPC : r ? -EINVAL : 0;
}

int coord_add_line(struct motmod *m, const struct motion_command *c, bool probe)
{
	struct tp_move mv;
	struct tp_pose end;

	fill_move(m, c, &mv);
	if (probe)
		mv.motion_type = TP_MOTION_PROBING;
	else if (mv.motion_type != TP_MOTION_TRAVERSE && mv.motion_type != TP_MOTION_INDEXROTARY &&
		 mv.motion_type != TP_MOTION_TOOLCHANGE)
		mv.motion_type = TP_MOTION_FEED;
	cmd_to_tp(c, &end);
	return tp_result(tp_add_line(m->coord_tp->tp, &end, &mv));
}

int coord_add_circle(struct motmod *m, const struct motion_command *c)
{
	struct tp_move mv;
	struct tp_pose end;
	struct tp_cart center = { c->center[0], c->center[1], c->center[2] };
	struct tp_cart normal = { c->normal[0], c->normal[1], c->normal[2] };

	fill_move(m, c, &mv);
	mv.motion_type = TP_MOTION_ARC;
	cmd_to_tp(c, &end);
	return tp_result(tp_add_circle(m->coord_tp->tp, &end, &center, &normal, c->turn, &mv));
}

int coord_add_rigid_tap(struct motmod *m, const struct motion_command *c)
{
	struct tp_move mv;
	struct tp_pose end;

	fill_move(m, c, &mv);
	mv.motion_type = TP_MOTION_FEED;
	cmd_to_tp(c, &end);
	return tp_result(tp_add_rigid_tap(m->coord_tp->tp, &end, c->scale, &mv));
}

int coord_set_dout(struct motmod *m, int out, bool start, bool end)
{
	return tp_set_dout(m->coord_tp->tp, out, start, end) ? -EINVAL : 0;
}

int coord_set_aout(struct motmod *m, int out, double start, double end)
{
	return tp_set_aout(m->coord_tp->tp, out, start, end) ? -EINVAL : 0;
}

/* what the planner's outputs ask of the rest of motion this period */
static void apply_outputs(struct motmod *m, const struct tp_outputs *o)
{
	int i;

	for (i = 0; i < m->num_dout && i < 64; i++)
		if (o->dout_mask & (1ull << i))
			m->dout_state[i] = (o->dout_value >> i) & 1;
	for (i = 0; i < o->aout_count && i < TP_SEG_AIO_MAX; i++)
		if (o->aout[i].index >= 0 && o->aout[i].index < m->num_aout)
			m->aout_value[o->aout[i].index] = o->aout[i].value;
	for (i = 0; i < m->num_spindles; i++)
		m->spindle_tap_scale[i] = 1.0;
	if (o->spindle_sync && o->spindle_num >= 0 && o->spindle_num < m->num_spindles) {
		m->spindle_tap_scale[o->spindle_num] = o->spindle_speed_scale;
		if (o->spindle_index_request)
			*m->pins->spindle[o->spindle_num].index_enable = 1;
	}
	if (o->probe_tripped) {
		m->probing = false;
		m->probe_tripped = true;
		mot_pose_to_array(m->world_fb_ok ? &m->world_fb : &m->world_cmd, m->probed.v);
	} else if (o->probe_no_contact) {
		m->probing = false;
		/* the position once motion has stopped (update_inpos): the joints arrive
		 * a few periods after the planner, through the interpolators */
		m->probe_pos_pending = true;
		if (!(m->probe_type & 1)) {
			mot_error(m, (m->probe_type & 2) ? "G38.4 move finished without breaking contact." :
				  "G38.2 move finished without making contact.");
			m->error = true;
		}
		m->probe_tripped = false;
	}
}

static void run_planner(struct motmod *m, EmcPose *world)
{
	struct mot_coord *c = m->coord_tp;
	struct tp_inputs in;
	int s = c->sync_spindle;

	memset(&in, 0, sizeof(in));
	in.feed_scale = m->net_feed_scale_coord;
	in.rapid_scale = m->net_rapid_scale;
	if (s < m->num_spindles) {
		struct mot_spindle_pins *sp = &m->pins->spindle[s];

		in.spindle_revs = *sp->revs;
		in.spindle_speed = *sp->speed_in;
		in.spindle_at_speed = *sp->at_speed;
		in.spindle_index_enable = *sp->index_enable;
	} else {
		in.spindle_at_speed = 1;
	}
	in.probe_input = *m->pins->probe_input;
	tp_run_cycle(c->tp, &in, &c->out);
	apply_outputs(m, &c->out);
	from_tp(&c->out.pos, world);
}

void coord_cycle(struct motmod *m, EmcPose *world)
{
	struct mot_coord *c = m->coord_tp;
	double joints[KINS_MAX_JOINTS];
	int j, nkins = m->num_joints - m->num_extrajoints;

	while (cubic_needs_next_point(&c->cubic[0]) || !c->filled) {
		run_planner(m, world);
		for (j = 0; j < KINS_MAX_JOINTS; j++)
			joints[j] = j < m->num_joints ? m->joint[j].pos_cmd : 0.0;
		if (mot_world_to_joints(m, world, joints) < 0)
			return;
		for (j = 0; j < nkins; j++) {
			cubic_add_point(&c->cubic[j], joints[j]);
			m->joint[j].coarse_pos = joints[j];
		}
		c->filled = true;
	}
	for (j = 0; j < nkins; j++) {
		struct mot_joint *jt = &m->joint[j];
		double vel = 0.0, acc = 0.0;

		jt->pos_cmd = cubic_interpolate(&c->cubic[j], &vel, &acc);
		jt->vel_cmd = vel;
	}
}

bool coord_is_done(struct motmod *m)
{
	return tp_is_done(m->coord_tp->tp) != 0;
}

int coord_depth(struct motmod *m)
{
	return tp_queue_depth(m->coord_tp->tp);
}

void coord_debug_params(struct motmod *m)
{
	struct mot_pins *p = m->pins;
	double pos, vel, acc;
	int i;

	/* traj: the executing segment's progress and the path speed */
	p->traj_pos_out = tp_segment_info(m->coord_tp->tp, 0, &pos, &vel, &acc) ? 0.0 : pos;
	p->traj_vel_out = m->coord_tp->out.current_vel;
	p->traj_active_tc = (hal_u32_t)m->coord_tp->out.active_depth;
	for (i = 0; i < 4; i++) {
		if (tp_segment_info(m->coord_tp->tp, i, &pos, &vel, &acc))
			pos = vel = acc = 0.0;
		p->tc_pos[i] = pos;
		p->tc_vel[i] = vel;
		p->tc_acc[i] = acc;
	}
}

void coord_status(struct motmod *m, rtapi_s32 *id, rtapi_s32 *motion_type, double *current_vel,
		  double *requested_vel, double *distance_to_go, int *active_depth, bool *queue_full)
{
	const struct tp_outputs *o = &m->coord_tp->out;

	*id = o->exec_id;
	*motion_type = o->motion_type;
	*current_vel = o->current_vel;
	*requested_vel = o->requested_vel;
	*distance_to_go = o->distance_to_go;
	*active_depth = o->active_depth;
	*queue_full = tp_is_queue_full(m->coord_tp->tp) != 0;
}
