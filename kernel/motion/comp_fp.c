/* SPDX-License-Identifier: GPL-2.0-or-later */
/* comp_fp.c - comp table, correction and filter (comp.h). FP only. */
#include "comp.h"
#include "rtapi_math.h"

#define COMP_FAR 1e300	/* the bracketing entries: beyond any machine position */

static void set_brackets(struct comp_table *t)
{
	int n = t->count, i;
	struct comp_point *first = &t->pt[1], *last = &t->pt[n];

	t->pt[0].nominal = -COMP_FAR;
	t->pt[n + 1].nominal = COMP_FAR;
	t->pt[0].fwd_trim = n ? first->fwd_trim : 0.0;
	t->pt[0].rev_trim = n ? first->rev_trim : 0.0;
	t->pt[n + 1].fwd_trim = n ? last->fwd_trim : 0.0;
	t->pt[n + 1].rev_trim = n ? last->rev_trim : 0.0;
	for (i = 0; i <= n; i++) {
		struct comp_point *a = &t->pt[i], *b = &t->pt[i + 1];

		if (i == 0 || i == n) {	/* flat beyond the table */
			a->fwd_slope = a->rev_slope = 0.0;
		} else {
			double span = b->nominal - a->nominal;

			a->fwd_slope = (b->fwd_trim - a->fwd_trim) / span;
			a->rev_slope = (b->rev_trim - a->rev_trim) / span;
		}
	}
	t->pt[n + 1].fwd_slope = t->pt[n + 1].rev_slope = 0.0;
}

void comp_table_clear(struct comp_table *t)
{
	t->count = 0;
	set_brackets(t);
}

int comp_table_add(struct comp_table *t, double nominal, double fwd_trim, double rev_trim)
{
	struct comp_point *p;

	if (!rtapi_isfinite(nominal) || !rtapi_isfinite(fwd_trim) || !rtapi_isfinite(rev_trim) ||
	    rtapi_fabs(nominal) >= COMP_FAR)
		return COMP_ADD_NOT_FINITE;
	if (t->count >= MOTION_COMP_SIZE)
		return COMP_ADD_FULL;
	if (t->count > 0 && nominal <= t->pt[t->count].nominal)
		return COMP_ADD_ORDER;
	t->count++;
	p = &t->pt[t->count];
	p->nominal = nominal;
	p->fwd_trim = fwd_trim;
	p->rev_trim = rev_trim;
	set_brackets(t);
	return COMP_ADD_OK;
}

double comp_correction(const struct comp_table *t, double backlash, double pos, double vel,
		       double prev)
{
	int lo, hi;
	const struct comp_point *p;

	if (vel == 0.0)
		return prev;
	if (t->count == 0)
		return vel > 0.0 ? 0.5 * backlash : -0.5 * backlash;
	/* binary search of the interval [pt[lo], pt[lo + 1]) holding pos */
	lo = 0;
	hi = t->count + 1;
	while (hi - lo > 1) {
		int mid = (lo + hi) / 2;

		if (pos >= t->pt[mid].nominal)
			lo = mid;
		else
			hi = mid;
	}
	p = &t->pt[lo];
	if (lo == 0)	/* before the first point: its trims */
		return vel > 0.0 ? t->pt[1].fwd_trim : t->pt[1].rev_trim;
	if (vel > 0.0)
		return p->fwd_trim + p->fwd_slope * (pos - p->nominal);
	return p->rev_trim + p->rev_slope * (pos - p->nominal);
}

void comp_filter(double corr, double *filt, double *vel, double max_vel, double max_acc,
		 double period_s)
{
	double dist = corr - *filt;
	double dv = max_acc * period_s;
	double v = *vel, stop_dist, target_v;

	if (max_vel <= 0.0 || max_acc <= 0.0 || period_s <= 0.0) {
		*vel = 0.0;	/* no motion allowed (feed hold): hold the correction */
		return;
	}
	/* close enough to land this period at a velocity the limits allow: snap */
	if (rtapi_fabs(dist) <= rtapi_fabs(v) * period_s + 0.5 * dv * period_s &&
	    rtapi_fabs(v) <= dv) {
		*filt = corr;
		*vel = 0.0;
		return;
	}
	/* highest speed toward corr from which max_acc still stops at it */
	stop_dist = rtapi_fabs(dist);
	target_v = -dv + rtapi_sqrt(dv * dv + 2.0 * max_acc * stop_dist);
	if (target_v > max_vel)
		target_v = max_vel;
	if (dist < 0.0)
		target_v = -target_v;
	if (target_v > v + dv)
		v += dv;
	else if (target_v < v - dv)
		v -= dv;
	else
		v = target_v;
	*filt += v * period_s;
	*vel = v;
}
