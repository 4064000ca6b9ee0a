/* SPDX-License-Identifier: GPL-2.0-or-later */
/* motmod_init_fp.c - motmod's initial float values (load time, called by motmod.c
 * between rtapi_fpu_begin() and rtapi_fpu_end()): the defaults LinuxCNC's motion
 * starts with until task configures it, and the pins' defaults. */
#include "motmod_priv.h"
#include "coord.h"

#define BIG 1e99	/* "no limit" */

int mot_init_values(struct motmod *m)
{
	int j, l, s;

	mot_error_attach(m);
	m->servo_period_s = m->servo_period_ns * 1e-9;
	m->feed_scale = m->rapid_scale = 1.0;
	m->net_feed_scale = m->net_rapid_scale = m->net_feed_scale_coord = 1.0;
	m->max_feed_scale = 1.0;
	m->enables_new = MOTION_FS_ENABLED | MOTION_SS_ENABLED;
	m->traj_vel = m->traj_acc = m->traj_vel_limit = BIG;
	m->term_cond = MOTION_TERM_STOP;
	m->inpos = true;
	m->state = MOTION_DISABLED;
	for (j = 0; j < MOTION_MAX_JOINTS; j++) {
		struct mot_joint *jt = &m->joint[j];

		/* LinuxCNC's values before task sends the [JOINT_n] ones */
		jt->min_limit = -1.0;
		jt->max_limit = 1.0;
		jt->vel_limit = 1.0;
		jt->acc_limit = 1.0;
		jt->min_ferror = 0.01;
		jt->max_ferror = 1.0;
		jt->free.max_vel = 1.0;
		jt->free.max_acc = 1.0;
		comp_table_clear(&jt->comp);
	}
	for (l = 0; l < MOTION_MAX_AXES; l++) {
		struct mot_axis *ax = &m->axis[l];

		ax->min_limit = -1.0;
		ax->max_limit = 1.0;
		ax->vel_limit = 1.0;
		ax->acc_limit = 1.0;
		ax->tp.max_vel = 1.0;
		ax->tp.max_acc = 1.0;
		ax->locking_joint = -1;
	}
	for (s = 0; s < MOTION_MAX_SPINDLES; s++) {
		struct mot_spindle *sp = &m->spindle[s];

		sp->scale = 1.0;
		sp->net_scale = 1.0;
		sp->min_fwd = 0.0;
		sp->max_fwd = BIG;
		sp->min_rev = 0.0;
		sp->max_rev = BIG;
		sp->increment = 100.0;
		sp->brake = 1;
		m->spindle_tap_scale[s] = 1.0;
	}
	return coord_init_values(m);
}

void mot_init_pin_values(struct motmod *m)
{
	struct mot_pins *p = m->pins;
	int j, l, s;

	*p->enable = 1;
	*p->adaptive_feed = 1.0;
	for (j = 0; j < m->num_joints; j++)
		*p->joint[j].jog_accel_fraction = 1.0;
	for (l = 0; l < MOTION_MAX_AXES; l++)
		*p->axis[l].jog_accel_fraction = 1.0;
	for (s = 0; s < m->num_spindles; s++) {
		*p->spindle[s].at_speed = 1;
		*p->spindle[s].brake = 1;
	}
}
