/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_math.c - the exact functions of rtapi_math.h (rounding, fmod, sign and NaN
 * tests), done on the IEEE bit patterns so that neither flavor needs libm. The
 * elementary functions are in rtapi_math_exp.c and rtapi_math_trig.c. */
#define RTAPI_MATH_NO_MACROS
#include "rtapi_math.h"
#include "rtapi_math_dd.h"

int rtapi_isnan(double x)
{
	return (rtm_bits(x) & ~RTM_SIGN) > RTM_EXP;
}

int rtapi_isinf(double x)
{
	return (rtm_bits(x) & ~RTM_SIGN) == RTM_EXP;
}

int rtapi_isfinite(double x)
{
	return (rtm_bits(x) & RTM_EXP) != RTM_EXP;
}

double rtapi_fabs(double x)
{
	return rtm_from_bits(rtm_bits(x) & ~RTM_SIGN);
}

double rtapi_copysign(double x, double y)
{
	return rtm_from_bits((rtm_bits(x) & ~RTM_SIGN) | (rtm_bits(y) & RTM_SIGN));
}

/* Compiled with -fno-math-errno this is one instruction (sqrtsd), never a libm call. */
double rtapi_sqrt(double x)
{
	return __builtin_sqrt(x);
}

double rtapi_trunc(double x)
{
	rtapi_u64 u = rtm_bits(x);
	int e = (int)((u >> 52) & 0x7ff) - 1023;

	if (e >= 52)		/* already integral, or inf/NaN */
		return x;
	if (e < 0)		/* |x| < 1 */
		return rtm_from_bits(u & RTM_SIGN);
	return rtm_from_bits(u & ~((1ULL << (52 - e)) - 1));
}

double rtapi_floor(double x)
{
	double t = rtapi_trunc(x);

	return t > x ? t - 1.0 : t;
}

double rtapi_ceil(double x)
{
	double t = rtapi_trunc(x);

	return t < x ? t + 1.0 : t;
}

double rtapi_round(double x)
{
	double t = rtapi_trunc(x);

	if (rtapi_fabs(x - t) >= 0.5)	/* x - t is exact */
		t += rtapi_copysign(1.0, x);
	return t;
}

/* Adding and removing 2^52 rounds to an integer in the current rounding mode. */
double rtapi_rint(double x)
{
	double big, r;

	if ((rtm_bits(x) & ~RTM_SIGN) >= 0x4330000000000000ULL)	/* |x| >= 2^52, inf, NaN */
		return x;
	big = rtapi_copysign(0x1p52, x);
	r = (x + big) - big;
	return rtapi_copysign(r, x);	/* rint(-0.3) is -0 */
}

double rtapi_fmin(double x, double y)
{
	if (rtapi_isnan(x))
		return y;
	if (rtapi_isnan(y))
		return x;
	if (x == y)		/* prefer -0 over +0 */
		return (rtm_bits(x) & RTM_SIGN) ? x : y;
	return x < y ? x : y;
}

double rtapi_fmax(double x, double y)
{
	if (rtapi_isnan(x))
		return y;
	if (rtapi_isnan(y))
		return x;
	if (x == y)		/* prefer +0 over -0 */
		return (rtm_bits(x) & RTM_SIGN) ? y : x;
	return x > y ? x : y;
}

/* Split a finite nonzero |x| into a 53-bit integer mantissa (implicit bit set) and a
 * biased exponent that may go below 1 for subnormals. */
static rtapi_u64 fmod_unpack(rtapi_u64 u, int *e)
{
	rtapi_u64 m = u & RTM_MANT;

	*e = (int)(u >> 52);
	if (*e == 0) {
		*e = 1;
		while (!(m & RTM_IMPLICIT)) {
			m <<= 1;
			(*e)--;
		}
		return m;
	}
	return m | RTM_IMPLICIT;
}

/* Exact remainder by binary long division of the mantissas: x - n*y, n = trunc(x/y). */
double rtapi_fmod(double x, double y)
{
	rtapi_u64 ux = rtm_bits(x), uy = rtm_bits(y);
	rtapi_u64 sx = ux & RTM_SIGN, mx, my;
	int ex, ey;

	ux &= ~RTM_SIGN;
	uy &= ~RTM_SIGN;
	if (uy == 0 || ux >= RTM_EXP || uy > RTM_EXP)	/* y = 0, x inf/NaN, y NaN */
		return (x * y) / (x * y);
	if (ux < uy)		/* |x| < |y| (bit order = value order) */
		return x;
	if (ux == uy)
		return rtm_from_bits(sx);
	mx = fmod_unpack(ux, &ex);
	my = fmod_unpack(uy, &ey);
	for (; ex > ey; ex--) {
		if (mx >= my) {
			mx -= my;
			if (mx == 0)
				return rtm_from_bits(sx);
		}
		mx <<= 1;
	}
	if (mx >= my) {
		mx -= my;
		if (mx == 0)
			return rtm_from_bits(sx);
	}
	while (mx < RTM_IMPLICIT) {
		mx <<= 1;
		ex--;
	}
	if (ex > 0)
		return rtm_from_bits(sx | ((rtapi_u64)ex << 52) | (mx & RTM_MANT));
	return rtm_from_bits(sx | (mx >> (1 - ex)));	/* subnormal: exact, no bits lost */
}

/* y * 2^k with a single rounding, also when the result is subnormal. */
double rtm_scale(double y, int k)
{
	if (k > 1023) {
		y *= 0x1p1023;
		k -= 1023;
		if (k > 1023)
			k = 1023;	/* overflows to inf anyway */
	}
	if (k < -1022) {
		if (k < -1200)
			k = -1200;	/* underflows to 0 anyway */
		return (y * rtm_pow2(k + 600)) * 0x1p-600;
	}
	return y * rtm_pow2(k);
}
