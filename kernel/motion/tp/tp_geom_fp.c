/* tp_geom_fp.c - segment geometry: where a segment is after s units of path, and
 * its direction there.  Lines, helices/spirals and 9D blend arcs (FP only). */
#include "tp_internal.h"
#include "rtapi_math.h"

double tp_dot(const double *a, const double *b, int n)
{
	double s = 0;
	for (int i = 0; i < n; i++)
		s += a[i] * b[i];
	return s;
}

double tp_norm(const double *v, int n)
{
	return rtapi_sqrt(tp_dot(v, v, n));
}

void pose_to_vec(const struct tp_pose *p, double v[TP_N])
{
	v[0] = p->x; v[1] = p->y; v[2] = p->z;
	v[3] = p->a; v[4] = p->b; v[5] = p->c;
	v[6] = p->u; v[7] = p->v; v[8] = p->w;
}

void vec_to_pose(const double v[TP_N], struct tp_pose *p)
{
	p->x = v[0]; p->y = v[1]; p->z = v[2];
	p->a = v[3]; p->b = v[4]; p->c = v[5];
	p->u = v[6]; p->v = v[7]; p->w = v[8];
}

/* Path length of a straight move (§10.1): XYZ if it moves, else UVW, else ABC.
 * group: 0 XYZ, 1 UVW, 2 ABC; -1 when axes outside the measuring group move too. */
static double line_length(const double d[TP_N], int *group)
{
	double xyz = tp_norm(d, 3), abc = tp_norm(d + 3, 3), uvw = tp_norm(d + 6, 3);
	if (xyz > TP_EPS) {
		*group = (abc > TP_EPS || uvw > TP_EPS) ? -1 : 0;
		return xyz;
	}
	if (uvw > TP_EPS) {
		*group = abc > TP_EPS ? -1 : 1;
		return uvw;
	}
	*group = 2;
	return abc;
}

int tc_line_init(struct tc *tc, const double start[TP_N], const double end[TP_N])
{
	double d[TP_N];
	for (int i = 0; i < TP_N; i++) {
		tc->start[i] = start[i];
		tc->end[i] = end[i];
		d[i] = end[i] - start[i];
	}
	tc->kind = TC_LINE;
	tc->len = line_length(d, &tc->linear_group);
	tc->pure_rotary = tc->linear_group == 2;
	if (tc->len <= TP_EPS)
		return TP_ERR_ZERO_LENGTH;
	for (int i = 0; i < TP_N; i++)
		tc->dir[i] = d[i] / tc->len;
	return 0;
}

static void cross3(const double a[3], const double b[3], double o[3])
{
	o[0] = a[1] * b[2] - a[2] * b[1];
	o[1] = a[2] * b[0] - a[0] * b[2];
	o[2] = a[0] * b[1] - a[1] * b[0];
}

int tc_circle_init(struct tc *tc, const double start[TP_N], const double end[TP_N],
		   const struct tp_cart *center, const struct tp_cart *normal, int turn)
{
	double n[3] = { normal->x, normal->y, normal->z };
	double c[3] = { center->x, center->y, center->z };
	double nn = tp_norm(n, 3), sv[3], ev[3], r0v[3], r1v[3];
	if (!(nn > TP_EPS) || turn < 0)
		return TP_ERR_INVALID;
	for (int i = 0; i < 3; i++) {
		n[i] /= nn;
		sv[i] = start[i] - c[i];
		ev[i] = end[i] - c[i];
	}
	double h0 = tp_dot(sv, n, 3), h1 = tp_dot(ev, n, 3);
	for (int i = 0; i < 3; i++) {
		r0v[i] = sv[i] - h0 * n[i];
		r1v[i] = ev[i] - h1 * n[i];
	}
	double r0 = tp_norm(r0v, 3), r1 = tp_norm(r1v, 3);
	if (!(r0 > TP_EPS) || !(r1 > TP_EPS))
		return TP_ERR_INVALID;
	for (int i = 0; i < 3; i++) {
		tc->n[i] = n[i];
		tc->c[i] = c[i];
		tc->e1[i] = r0v[i] / r0;
	}
	cross3(tc->n, tc->e1, tc->e2);
	double ang = rtapi_atan2(tp_dot(r1v, tc->e2, 3), tp_dot(r1v, tc->e1, 3));
	if (ang < 0)
		ang += 2 * TP_PI;
	if (ang < 1e-9)		/* end on the start radius: a full circle */
		ang = 2 * TP_PI;
	ang += 2 * TP_PI * turn;
	tc->kind = TC_CIRCLE;
	tc->angle = ang;
	tc->r0 = r0;
	tc->dr = r1 - r0;
	tc->h0 = h0;
	tc->dh = h1 - h0;
	double rmin = r0 < r1 ? r0 : r1;
	double spiral = rtapi_hypot(rmin * ang, tc->dr);
	tc->len = rtapi_hypot(spiral, tc->dh);
	tc->linear_group = -1;
	tc->pure_rotary = 0;
	for (int i = 0; i < TP_N; i++) {
		tc->start[i] = start[i];
		tc->end[i] = end[i];
		tc->dir[i] = i < 3 ? 0 : (end[i] - start[i]) / tc->len;
	}
	return 0;
}

void tc_pos_at(const struct tc *tc, double s, double out[TP_N])
{
	switch (tc->kind) {
	case TC_CIRCLE: {
		double f = s / tc->len, phi = f * tc->angle;
		double r = tc->r0 + tc->dr * f, h = tc->h0 + tc->dh * f;
		double cp = rtapi_cos(phi), sp = rtapi_sin(phi);
		for (int i = 0; i < 3; i++)
			out[i] = tc->c[i] + h * tc->n[i] + r * (cp * tc->e1[i] + sp * tc->e2[i]);
		for (int i = 3; i < TP_N; i++)
			out[i] = tc->start[i] + tc->dir[i] * s;
		if (s >= tc->len)	/* land exactly on the programmed end */
			for (int i = 0; i < TP_N; i++)
				out[i] = tc->end[i];
		return;
	}
	case TC_BLEND: {
		double phi = s / tc->br, cp = rtapi_cos(phi), sp = rtapi_sin(phi);
		for (int i = 0; i < TP_N; i++)
			out[i] = tc->bc[i] + tc->br * (cp * tc->b1[i] + sp * tc->b2[i]);
		if (s >= tc->len)
			for (int i = 0; i < TP_N; i++)
				out[i] = tc->end[i];
		return;
	}
	default:		/* TC_LINE, TC_TAP (s = signed position along dir) */
		if (tc->kind == TC_LINE && s >= tc->len) {
			for (int i = 0; i < TP_N; i++)
				out[i] = tc->end[i];
			return;
		}
		for (int i = 0; i < TP_N; i++)
			out[i] = tc->start[i] + tc->dir[i] * s;
		return;
	}
}

/* Unit direction (9D) of motion at the start (at_end = 0) or end of the segment. */
void tc_tangent(const struct tc *tc, int at_end, double u[TP_N])
{
	switch (tc->kind) {
	case TC_CIRCLE: {
		double f = at_end ? 1.0 : 0.0, phi = f * tc->angle;
		double r = tc->r0 + tc->dr * f, cp = rtapi_cos(phi), sp = rtapi_sin(phi);
		for (int i = 0; i < 3; i++)
			u[i] = (tc->dh * tc->n[i] + tc->dr * (cp * tc->e1[i] + sp * tc->e2[i])
				+ r * tc->angle * (-sp * tc->e1[i] + cp * tc->e2[i])) / tc->len;
		for (int i = 3; i < TP_N; i++)
			u[i] = tc->dir[i];
		break;
	}
	case TC_BLEND: {
		double phi = at_end ? tc->len / tc->br : 0.0;
		double cp = rtapi_cos(phi), sp = rtapi_sin(phi);
		for (int i = 0; i < TP_N; i++)
			u[i] = -sp * tc->b1[i] + cp * tc->b2[i];
		break;
	}
	default:
		for (int i = 0; i < TP_N; i++)
			u[i] = tc->dir[i];
		break;
	}
	double m = tp_norm(u, TP_N);
	if (m > TP_EPS)
		for (int i = 0; i < TP_N; i++)
			u[i] /= m;
}
