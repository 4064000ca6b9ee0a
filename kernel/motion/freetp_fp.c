/* SPDX-License-Identifier: GPL-2.0-or-later */
/* freetp_fp.c - the free-mode trapezoid planner (freetp.h). FP only. */
#include "freetp.h"
#include "rtapi_math.h"

void freetp_update(struct freetp *tp, double period_s)
{
	double max_dv = tp->max_acc * period_s;
	/* below this a position error is noise: stop instead of dithering (TINY_DP) */
	double tiny_dp = tp->max_acc * period_s * period_s * 0.001;
	double vel_req = 0.0;

	if (tp->max_acc <= 0.0 || tp->max_vel <= 0.0 || period_s <= 0.0) {
		tp->curr_vel = 0.0;
		tp->active = false;
		return;
	}
	if (tp->enable) {
		double err = tp->pos_cmd - tp->curr_pos;

		/* the velocity from which braking at max_acc ends exactly at the target,
		 * accounting for the one-period delay of the position update */
		if (err > tiny_dp)
			vel_req = -max_dv + rtapi_sqrt(2.0 * tp->max_acc * err + max_dv * max_dv);
		else if (err < -tiny_dp)
			vel_req = max_dv - rtapi_sqrt(-2.0 * tp->max_acc * err + max_dv * max_dv);
	} else {
		tp->pos_cmd = tp->curr_pos;
	}
	if (vel_req > tp->max_vel)
		vel_req = tp->max_vel;
	else if (vel_req < -tp->max_vel)
		vel_req = -tp->max_vel;
	if (vel_req > tp->curr_vel + max_dv)
		tp->curr_vel += max_dv;
	else if (vel_req < tp->curr_vel - max_dv)
		tp->curr_vel -= max_dv;
	else
		tp->curr_vel = vel_req;
	/* a lowered max_vel is reached by decelerating at max_acc, never by a jump */
	tp->active = tp->curr_vel != 0.0 ||
		     (tp->enable && rtapi_fabs(tp->pos_cmd - tp->curr_pos) > tiny_dp);
	tp->curr_pos += tp->curr_vel * period_s;
	/* arrived (stopped within noise of the target): land on it exactly */
	if (tp->enable && tp->curr_vel == 0.0 && rtapi_fabs(tp->pos_cmd - tp->curr_pos) <= tiny_dp) {
		tp->curr_pos = tp->pos_cmd;
		tp->active = false;
	}
}

void freetp_reset(struct freetp *tp, double pos)
{
	tp->curr_pos = pos;
	tp->pos_cmd = pos;
	tp->curr_vel = 0.0;
	tp->active = false;
}
