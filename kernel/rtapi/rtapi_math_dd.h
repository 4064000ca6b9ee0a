/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_math_dd.h - private helpers of rtapi_math*.c: IEEE bit access and "double-double"
 * arithmetic (a value held as hi + lo, about 106 bits), which lets the elementary
 * functions round their final result only once. Plain C, no libc. The error-free
 * transformations below need strict IEEE double evaluation: the files that include this
 * header are compiled with -ffp-contract=off (no fused multiply-add). */
#ifndef RTAPI_MATH_DD_H
#define RTAPI_MATH_DD_H

#include "rtapi.h"

#define RTM_SIGN	0x8000000000000000ULL
#define RTM_EXP		0x7ff0000000000000ULL
#define RTM_MANT	0x000fffffffffffffULL
#define RTM_IMPLICIT	0x0010000000000000ULL

struct rtm_dd {
	double hi;	/* the value rounded to double */
	double lo;	/* what hi is missing, |lo| <= ulp(hi)/2 once normalized */
};

static inline rtapi_u64 rtm_bits(double x)
{
	union { double d; rtapi_u64 u; } b;

	b.d = x;
	return b.u;
}

static inline double rtm_from_bits(rtapi_u64 u)
{
	union { double d; rtapi_u64 u; } b;

	b.u = u;
	return b.d;
}

/* 2^n for -1022 <= n <= 1023 */
static inline double rtm_pow2(int n)
{
	return rtm_from_bits((rtapi_u64)(n + 1023) << 52);
}

/* Nearest integer (ties to even) of |x| < 2^51, as a double. */
static inline double rtm_nearest(double x)
{
	return (x + 0x1.8p52) - 0x1.8p52;
}

/* s + e == a + b exactly (Knuth). */
static inline struct rtm_dd rtm_two_sum(double a, double b)
{
	struct rtm_dd r;
	double bv, av;

	r.hi = a + b;
	bv = r.hi - a;
	av = r.hi - bv;
	r.lo = (a - av) + (b - bv);
	return r;
}

/* Same, when |a| >= |b| or a == 0 (Dekker). */
static inline struct rtm_dd rtm_fast_two_sum(double a, double b)
{
	struct rtm_dd r;

	r.hi = a + b;
	r.lo = b - (r.hi - a);
	return r;
}

/* p + e == a * b exactly (Dekker/Veltkamp splitting; |a|, |b| < 2^995). */
static inline struct rtm_dd rtm_two_prod(double a, double b)
{
	struct rtm_dd r;
	double t, ah, al, bh, bl;

	t = 134217729.0 * a;	/* 2^27 + 1 */
	ah = t - (t - a);
	al = a - ah;
	t = 134217729.0 * b;
	bh = t - (t - b);
	bl = b - bh;
	r.hi = a * b;
	r.lo = ((ah * bh - r.hi) + ah * bl + al * bh) + al * bl;
	return r;
}

static inline struct rtm_dd rtm_dd_make(double hi, double lo)
{
	return rtm_fast_two_sum(hi, lo);
}

static inline struct rtm_dd rtm_dd_add(struct rtm_dd a, struct rtm_dd b)
{
	struct rtm_dd s = rtm_two_sum(a.hi, b.hi);

	return rtm_fast_two_sum(s.hi, s.lo + (a.lo + b.lo));
}

static inline struct rtm_dd rtm_dd_neg(struct rtm_dd a)
{
	a.hi = -a.hi;
	a.lo = -a.lo;
	return a;
}

static inline struct rtm_dd rtm_dd_sub(struct rtm_dd a, struct rtm_dd b)
{
	return rtm_dd_add(a, rtm_dd_neg(b));
}

static inline struct rtm_dd rtm_dd_mul(struct rtm_dd a, struct rtm_dd b)
{
	struct rtm_dd p = rtm_two_prod(a.hi, b.hi);

	return rtm_fast_two_sum(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}

static inline struct rtm_dd rtm_dd_mul_d(struct rtm_dd a, double b)
{
	struct rtm_dd p = rtm_two_prod(a.hi, b);

	return rtm_fast_two_sum(p.hi, p.lo + a.lo * b);
}

/* a / b, one correction step: good to about 2^-104 relative. */
static inline struct rtm_dd rtm_dd_div(struct rtm_dd a, struct rtm_dd b)
{
	double q1 = a.hi / b.hi;
	struct rtm_dd p = rtm_two_prod(q1, b.hi);
	double rem = ((a.hi - p.hi) - p.lo) + a.lo - q1 * b.lo;

	return rtm_fast_two_sum(q1, rem / b.hi);
}

/* sqrt of a dd (a.hi > 0), one Newton correction. */
static inline struct rtm_dd rtm_dd_sqrt(struct rtm_dd a)
{
	double h = __builtin_sqrt(a.hi);
	struct rtm_dd p = rtm_two_prod(h, h);

	return rtm_fast_two_sum(h, (((a.hi - p.hi) - p.lo) + a.lo) / (2.0 * h));
}

/* Internal entry points shared between the rtapi_math*.c files. */
int rtm_exp_core(double xh, double xl, struct rtm_dd *m);	/* e^x = m * 2^k, returns k */
double rtm_scale(double y, int k);				/* y * 2^k, one rounding */

#endif /* RTAPI_MATH_DD_H */
