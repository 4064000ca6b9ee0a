/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_math_exp.c - exp, log, log10, pow, sinh, cosh, tanh and hypot for rtapi_math.h,
 * written without libm. Each works in double-double (rtapi_math_dd.h) and rounds once
 * at the end, which keeps pow within 1 ULP even for |y*log(x)| near 700. */
#define RTAPI_MATH_NO_MACROS
#include "rtapi_math.h"
#include "rtapi_math_dd.h"

/* ln 2 split so that k * LN2_HI is exact for |k| < 2^13 */
#define LN2_HI		0x1.62e42fefa2000p-1
#define LN2_LO		0x1.9ef35793c7673p-41
#define INV_LN2		0x1.71547652b82fep+0
#define SQRT2		0x1.6a09e667f3bcdp+0

static const struct rtm_dd two_thirds = { 0x1.5555555555555p-1, 0x1.5555555555555p-55 };
static const struct rtm_dd inv_ln10 = { 0x1.bcb7b1526e50ep-2, 0x1.95355baaafad3p-57 };

/* e^(xh + xl) = m * 2^k for |xh| < 1000: k = nearest(x / ln 2), r = x - k ln 2
 * (|r| <= 0.35) and m = e^r by its Taylor series through r^14, whose remainder is
 * below 2^-57. m is returned as a normalized double-double. */
int rtm_exp_core(double xh, double xl, struct rtm_dd *m)
{
	double kd = rtm_nearest(xh * INV_LN2);
	double z, p, tail;
	struct rtm_dd r, s;

	r = rtm_two_sum(xh - kd * LN2_HI, xl - kd * LN2_LO);	/* first term exact */
	z = r.hi;
	p = 1.0 / 479001600.0 + z * (1.0 / 6227020800.0 + z * (1.0 / 87178291200.0));
	p = 1.0 / 3628800.0 + z * (1.0 / 39916800.0 + z * p);
	p = 1.0 / 40320.0 + z * (1.0 / 362880.0 + z * p);
	p = 1.0 / 720.0 + z * (1.0 / 5040.0 + z * p);
	p = 1.0 / 2.0 + z * (1.0 / 6.0 + z * (1.0 / 24.0 + z * (1.0 / 120.0 + z * p)));
	tail = z * z * p + r.lo * (1.0 + z);	/* e^r - 1 - r.hi */
	s = rtm_fast_two_sum(1.0, z);
	*m = rtm_fast_two_sum(s.hi, s.lo + tail);
	return (int)kd;
}

/* e^x as a double-double, for |x| <= 64 (no overflow). */
static struct rtm_dd exp_dd(double x)
{
	struct rtm_dd m;
	double s = rtm_pow2(rtm_exp_core(x, 0.0, &m));

	m.hi *= s;
	m.lo *= s;
	return m;
}

double rtapi_exp(double x)
{
	struct rtm_dd m;
	int k;

	if (rtapi_isnan(x))
		return x + x;
	if (x > 1000.0)
		return __builtin_inf();
	if (x < -1000.0)
		return 0.0;
	if (rtapi_fabs(x) < 0x1p-54)
		return 1.0 + x;
	k = rtm_exp_core(x, 0.0, &m);
	return rtm_scale(m.hi + m.lo, k);
}

/* log(x) as a double-double for finite x > 0: x = 2^k * m with m in [sqrt(1/2), sqrt(2)),
 * log(m) = 2 atanh(s) = 2s + 2s^3/3 + 2s^5/5 + ..., s = (m-1)/(m+1), |s| < 0.172.
 * The first two terms are kept in double-double, the rest (< 2^-12 of the result) in
 * double; the series is cut at s^31 (remainder < 2^-76 relative). */
static struct rtm_dd log_dd(double x)
{
	rtapi_u64 u = rtm_bits(x);
	int k = 0;
	double m, f, z, p;
	struct rtm_dd s, s2, s3, res, kl;

	if (u < RTM_IMPLICIT) {		/* subnormal */
		x *= 0x1p54;
		u = rtm_bits(x);
		k = -54;
	}
	k += (int)(u >> 52) - 1023;
	m = rtm_from_bits((u & RTM_MANT) | 0x3ff0000000000000ULL);
	if (m > SQRT2) {
		m *= 0.5;
		k++;
	}
	f = m - 1.0;		/* exact */
	s = rtm_dd_div(rtm_dd_make(f, 0.0), rtm_two_sum(2.0, f));
	s2 = rtm_dd_mul(s, s);
	s3 = rtm_dd_mul(s2, s);
	z = s2.hi;
	p = 2.0 / 25 + z * (2.0 / 27 + z * (2.0 / 29 + z * (2.0 / 31)));
	p = 2.0 / 17 + z * (2.0 / 19 + z * (2.0 / 21 + z * (2.0 / 23 + z * p)));
	p = 2.0 / 5 + z * (2.0 / 7 + z * (2.0 / 9 + z * (2.0 / 11 + z * (2.0 / 13 + z * (2.0 / 15 + z * p)))));
	res = rtm_dd_add(rtm_dd_mul(s3, two_thirds), rtm_dd_make(s3.hi * z * p, 0.0));
	res = rtm_dd_add(rtm_dd_make(2.0 * s.hi, 2.0 * s.lo), res);
	kl = rtm_dd_make(k * LN2_HI, k * LN2_LO);	/* k * LN2_HI exact */
	return rtm_dd_add(kl, res);
}

/* NaN, -inf or +inf for the arguments where log has no finite value; 0 otherwise. */
static int log_special(double x, double *r)
{
	if (rtapi_isnan(x)) {
		*r = x + x;
		return 1;
	}
	if (x == 0.0) {
		*r = -__builtin_inf();
		return 1;
	}
	if (x < 0.0) {
		*r = __builtin_nan("");
		return 1;
	}
	if (rtapi_isinf(x)) {
		*r = x;
		return 1;
	}
	return 0;
}

double rtapi_log(double x)
{
	double r;

	if (log_special(x, &r))
		return r;
	if (x == 1.0)
		return 0.0;
	return log_dd(x).hi;
}

double rtapi_log10(double x)
{
	double r;

	if (log_special(x, &r))
		return r;
	if (x == 1.0)
		return 0.0;
	return rtm_dd_mul(log_dd(x), inv_ln10).hi;
}

/* 0: y is not an integer, 1: odd integer, 2: even integer. */
static int int_kind(double y)
{
	rtapi_u64 u = rtm_bits(y) & ~RTM_SIGN;
	int e = (int)(u >> 52) - 1023;
	rtapi_u64 m;

	if (e >= 53)
		return 2;
	if (e < 0)
		return 0;
	m = (u & RTM_MANT) | RTM_IMPLICIT;
	if (m & ((1ULL << (52 - e)) - 1))
		return 0;
	return ((m >> (52 - e)) & 1) ? 1 : 2;
}

/* pow's C99 Annex F special cases; returns 1 and sets *r when one applies. */
static int pow_special(double x, double y, int yk, double *r)
{
	double inf = __builtin_inf();

	if (y == 0.0 || x == 1.0) {
		*r = 1.0;
	} else if (rtapi_isnan(x) || rtapi_isnan(y)) {
		*r = x + y;
	} else if (rtapi_isinf(y)) {
		double ax = rtapi_fabs(x);

		if (ax == 1.0)
			*r = 1.0;
		else
			*r = ((ax > 1.0) == (y > 0.0)) ? inf : 0.0;
	} else if (x == 0.0) {
		if (y < 0.0)
			*r = yk == 1 ? rtapi_copysign(inf, x) : inf;
		else
			*r = yk == 1 ? x : 0.0;
	} else if (rtapi_isinf(x)) {
		if (x > 0.0)
			*r = y > 0.0 ? inf : 0.0;
		else if (y > 0.0)
			*r = yk == 1 ? -inf : inf;
		else
			*r = yk == 1 ? -0.0 : 0.0;
	} else if (x < 0.0 && yk == 0) {
		*r = __builtin_nan("");
	} else {
		return 0;
	}
	return 1;
}

/* x^y = e^(y log x) with log x in double-double. */
double rtapi_pow(double x, double y)
{
	int yk = int_kind(y);
	double r, sign = 1.0;
	struct rtm_dd l, p, m;
	int k;

	if (pow_special(x, y, yk, &r))
		return r;
	if (x < 0.0) {
		x = -x;
		if (yk == 1)
			sign = -1.0;
	}
	l = log_dd(x);
	r = l.hi * y;
	if (r > 1000.0)
		return sign * __builtin_inf();
	if (r < -1000.0)
		return sign * 0.0;
	p = rtm_dd_mul_d(l, y);
	k = rtm_exp_core(p.hi, p.lo, &m);
	return sign * rtm_scale(m.hi + m.lo, k);
}

/* e^a / 2 for 22 <= a, without overflowing before the halving. */
static double half_exp(double a)
{
	struct rtm_dd m;
	int k;

	if (a > 1000.0)
		return __builtin_inf();
	k = rtm_exp_core(a, 0.0, &m);
	return rtm_scale(m.hi + m.lo, k - 1);
}

double rtapi_sinh(double x)
{
	double a = rtapi_fabs(x), z, p, r;
	struct rtm_dd e, d;

	if (!rtapi_isfinite(x) || a < 0x1p-28)
		return x;	/* NaN, +-inf, and tiny x (sinh x = x to the last bit) */
	if (a < 1.0) {		/* Taylor series through x^21 */
		z = x * x;
		p = 1.0 / 39916800.0 + z * (1.0 / 6227020800.0 + z * (1.0 / 1307674368000.0 +
		    z * (1.0 / 355687428096000.0 + z * (1.0 / 121645100408832000.0 +
		    z * (1.0 / 51090942171709440000.0)))));
		p = 1.0 / 6.0 + z * (1.0 / 120.0 + z * (1.0 / 5040.0 + z * (1.0 / 362880.0 + z * p)));
		return x + x * z * p;
	}
	if (a < 22.0) {
		e = exp_dd(a);
		d = rtm_dd_sub(e, rtm_dd_div(rtm_dd_make(1.0, 0.0), e));
		r = 0.5 * (d.hi + d.lo);
	} else {
		r = half_exp(a);	/* e^-a is below half an ULP */
	}
	return x < 0.0 ? -r : r;
}

double rtapi_cosh(double x)
{
	double a = rtapi_fabs(x), z, p;
	struct rtm_dd e, d;

	if (rtapi_isnan(x))
		return x + x;
	if (a < 0x1p-27)
		return 1.0;
	if (a < 1.0) {		/* Taylor series through x^22 */
		z = x * x;
		p = 1.0 / 3628800.0 + z * (1.0 / 479001600.0 + z * (1.0 / 87178291200.0 +
		    z * (1.0 / 20922789888000.0 + z * (1.0 / 6402373705728000.0 +
		    z * (1.0 / 2432902008176640000.0 + z * (1.0 / 1124000727777607680000.0))))));
		p = 0.5 + z * (1.0 / 24.0 + z * (1.0 / 720.0 + z * (1.0 / 40320.0 + z * p)));
		d = rtm_fast_two_sum(1.0, z * p);
		return d.hi;
	}
	if (a < 22.0) {
		e = exp_dd(a);
		d = rtm_dd_add(e, rtm_dd_div(rtm_dd_make(1.0, 0.0), e));
		return 0.5 * (d.hi + d.lo);
	}
	return half_exp(a);
}

/* tanh x = (e^2x - 1) / (e^2x + 1), with e^2x - 1 kept in double-double so small x
 * loses nothing to the subtraction. */
double rtapi_tanh(double x)
{
	double a = rtapi_fabs(x), s;
	struct rtm_dd m, em1, r;

	if (rtapi_isnan(x) || a < 0x1p-28)
		return x;
	if (a > 22.0)		/* tanh(22) rounds to 1 */
		return x < 0.0 ? -1.0 : 1.0;
	s = rtm_pow2(rtm_exp_core(2.0 * a, 0.0, &m));
	em1 = rtm_dd_add(rtm_dd_make(m.hi * s, m.lo * s), rtm_dd_make(-1.0, 0.0));
	r = rtm_dd_div(em1, rtm_dd_add(em1, rtm_dd_make(2.0, 0.0)));
	return x < 0.0 ? -r.hi : r.hi;
}

/* sqrt(x^2 + y^2) with the squares exact in double-double, scaled so that neither
 * overflows nor underflows. */
double rtapi_hypot(double x, double y)
{
	double ax = rtapi_fabs(x), ay = rtapi_fabs(y), t, scale = 1.0;
	int ex, ey;
	struct rtm_dd s;

	if (rtapi_isinf(x) || rtapi_isinf(y))
		return __builtin_inf();
	if (rtapi_isnan(x) || rtapi_isnan(y))
		return x + y;
	if (ax < ay) {
		t = ax;
		ax = ay;
		ay = t;
	}
	if (ay == 0.0)
		return ax;
	ex = (int)(rtm_bits(ax) >> 52);
	ey = (int)(rtm_bits(ay) >> 52);
	if (ex - ey > 60)	/* ay^2 is below an ULP of ax^2 */
		return ax + ay;
	if (ex > 1023 + 500) {
		ax *= 0x1p-600;
		ay *= 0x1p-600;
		scale = 0x1p600;
	} else if (ex < 1023 - 450) {
		ax *= 0x1p600;
		ay *= 0x1p600;
		scale = 0x1p-600;
	}
	s = rtm_dd_add(rtm_two_prod(ax, ax), rtm_two_prod(ay, ay));
	return rtm_dd_sqrt(s).hi * scale;
}
