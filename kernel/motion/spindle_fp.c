/* SPDX-License-Identifier: GPL-2.0-or-later */
/* spindle_fp.c - spindle inputs (amp fault, orient handshake) and outputs (motion.md
 * 4.4, 14): override/inhibit, CSS, min/max clamps, on/forward/reverse/brake. */
#include "motmod_priv.h"
#include "rtapi_math.h"

void mot_spindle_inputs(struct motmod *m)
{
	int s;

	for (s = 0; s < m->num_spindles; s++) {
		struct mot_spindle *sp = &m->spindle[s];
		struct mot_spindle_pins *p = &m->pins->spindle[s];

		/* override (M48/M51 enable it), inhibit stops the spindle */
		sp->net_scale = (m->enables_new & MOTION_SS_ENABLED) ? sp->scale : 1.0;
		if (*p->inhibit)
			sp->net_scale = 0.0;
		if (m->enabled && *p->amp_fault_in) {
			if (!sp->fault_reported)
				mot_error(m, "spindle %d amplifier fault", s);
			sp->fault_reported = true;
			m->disable_req = true;
		} else if (!*p->amp_fault_in) {
			sp->fault_reported = false;
		}
		if (sp->orient_state == 1) {
			if (*p->orient_fault) {
				sp->orient_fault = *p->orient_fault;
				sp->orient_state = 3;
				*p->orient = 0;
				mot_error(m, "fault %d during orient in progress", sp->orient_fault);
			} else if (*p->is_oriented) {
				sp->orient_state = 2;
				*p->orient = 0;
				sp->locked = 1;
				sp->brake = 1;
			}
		}
	}
}

void mot_spindle_outputs(struct motmod *m)
{
	int s;

	for (s = 0; s < m->num_spindles; s++) {
		struct mot_spindle *sp = &m->spindle[s];
		struct mot_spindle_pins *p = &m->pins->spindle[s];
		double speed = sp->speed * m->spindle_tap_scale[s], out;

		if (sp->css_factor != 0.0 && sp->state) {
			double denom = rtapi_fabs(sp->xoffset - m->world_cmd.tran.x);
			double limit = rtapi_fabs(speed);

			out = denom > 0.0 ? sp->css_factor / denom : limit;
			out *= sp->net_scale;
			if (out > limit)
				out = limit;	/* G96 D: the commanded speed is the maximum */
			if (speed < 0.0)
				out = -out;
		} else {
			out = speed * sp->net_scale;
		}
		if (out > 0.0) {
			if (out < sp->min_fwd)
				out = sp->min_fwd;
			if (out > sp->max_fwd)
				out = sp->max_fwd;
		} else if (out < 0.0) {
			if (out > -sp->min_rev)
				out = -sp->min_rev;
			if (out < -sp->max_rev)
				out = -sp->max_rev;
		}
		if (!sp->state)
			out = 0.0;
		sp->speed_out = out;
		*p->speed_out = out;
		*p->speed_out_abs = rtapi_fabs(out);
		*p->speed_out_rps = out / 60.0;
		*p->speed_out_rps_abs = rtapi_fabs(out) / 60.0;
		*p->speed_cmd_rps = sp->speed / 60.0;
		*p->on = sp->state != 0;
		*p->forward = out > 0.0;
		*p->reverse = out < 0.0;
		*p->brake = sp->brake != 0;
		*p->locked = sp->locked != 0;
		*p->orient_angle = sp->orient_angle;
		*p->orient_mode = sp->orient_mode;
	}
}
