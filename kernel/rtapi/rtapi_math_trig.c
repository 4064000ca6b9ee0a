/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_math_trig.c - sin, cos, tan, asin, acos, atan, atan2 for rtapi_math.h, without
 * libm. Arguments are reduced modulo pi/2 in double-double: Cody-Waite with a 152-bit
 * pi/2 below 2^20 * pi/2, and Payne-Hanek with 1280 bits of 2/pi above, so even
 * sin(1e300) is accurate. The kernels are Taylor series on |r| <= pi/4. */
#define RTAPI_MATH_NO_MACROS
#include "rtapi_math.h"
#include "rtapi_math_dd.h"

#define PI_4		0x1.921fb54442d18p-1
#define TWO_OVER_PI	0x1.45f306dc9c883p-1
/* pi/2 = PIO2_1 + PIO2_2 + PIO2_3 + PIO2_3T; the first three have 33 significant bits,
 * so k * PIO2_n is exact for |k| < 2^20. */
#define PIO2_1		0x1.921fb54400000p+0
#define PIO2_2		0x1.0b4611a600000p-34
#define PIO2_3		0x1.3198a2e000000p-69
#define PIO2_3T		0x1.b839a252049c1p-104

static const struct rtm_dd pio2 = { 0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54 };
static const struct rtm_dd pi = { 0x1.921fb54442d18p+1, 0x1.1a62633145c07p-53 };

/* 2/pi in binary: bit 1 (value 2^-1) is the top bit of the first word. */
static const rtapi_u64 two_over_pi_bits[20] = {
	0xa2f9836e4e441529ULL, 0xfc2757d1f534ddc0ULL, 0xdb6295993c439041ULL,
	0xfe5163abdebbc561ULL, 0xb7246e3a424dd2e0ULL, 0x06492eea09d1921cULL,
	0xfe1deb1cb129a73eULL, 0xe88235f52ebb4484ULL, 0xe99c7026b45f7e41ULL,
	0x3991d639835339f4ULL, 0x9c845f8bbdf9283bULL, 0x1ff897ffde05980fULL,
	0xef2f118b5a0a6d1fULL, 0x6d367ecf27cb09b7ULL, 0x4f463f669e5fea2dULL,
	0x7527bac7ebe5f17bULL, 0x3d0739f78a5292eaULL, 0x6bfb5fb11f8d5d08ULL,
	0x56033046fc7b6babULL, 0xf0cfbc209af4361dULL,
};

/* atan(j/16) for j = 0..16, as double-doubles */
static const struct rtm_dd atan_j16[17] = {
	{ 0.0, 0.0 },
	{ 0x1.ff55bb72cfdeap-5, -0x1.c934d86d23f1dp-60 },
	{ 0x1.fd5ba9aac2f6ep-4, -0x1.cd37686760c17p-59 },
	{ 0x1.7b97b4bce5b02p-3, 0x1.347b0b4f881cap-58 },
	{ 0x1.f5b75f92c80ddp-3, 0x1.8ab6e3cf7afbdp-57 },
	{ 0x1.362773707ebccp-2, -0x1.963a544b672d8p-57 },
	{ 0x1.6f61941e4def1p-2, -0x1.c63aae6f6e918p-56 },
	{ 0x1.a64eec3cc23fdp-2, -0x1.24dec1b50b7ffp-56 },
	{ 0x1.dac670561bb4fp-2, 0x1.a2b7f222f65e2p-56 },
	{ 0x1.0657e94db30d0p-1, -0x1.d5b495f6349e6p-56 },
	{ 0x1.1e00babdefeb4p-1, -0x1.928df287a668fp-58 },
	{ 0x1.345f01cce37bbp-1, 0x1.1021137c71102p-55 },
	{ 0x1.4978fa3269ee1p-1, 0x1.2419a87f2a458p-56 },
	{ 0x1.5d58987169b18p-1, 0x1.0028e4bc5e7cap-57 },
	{ 0x1.700a7c5784634p-1, -0x1.8c34d25aadef6p-56 },
	{ 0x1.819d0b7158a4dp-1, -0x1.bf76229d3b917p-56 },
	{ 0x1.921fb54442d18p-1, 0x1.1a62633145c07p-55 },
};

/* 64 bits of 2/pi starting at bit position p (1 = first bit after the point); the
 * bits at positions <= 0 are zero. */
static rtapi_u64 two_over_pi_at(int p)
{
	int w, s, shift = 0;
	rtapi_u64 v;

	if (p <= -63)
		return 0;
	if (p < 1) {
		shift = 1 - p;
		p = 1;
	}
	w = (p - 1) / 64;
	s = (p - 1) % 64;
	v = two_over_pi_bits[w] << s;
	if (s)
		v |= two_over_pi_bits[w + 1] >> (64 - s);
	return v >> shift;
}

/* Payne-Hanek for |x| >= 2^20 * pi/2: with x = M * 2^e (M a 53-bit integer), the bits
 * of 2/pi worth 2^(e-i) * M >= 4 only add multiples of 4 to x * 2/pi, so a 192-bit
 * window starting at bit e-1 gives the quadrant and 128 fraction bits exactly. */
static int rem_pio2_large(double ax, struct rtm_dd *r)
{
	rtapi_u64 u = rtm_bits(ax);
	int e = (int)(u >> 52) - 1075;
	rtapi_u64 M = (u & RTM_MANT) | RTM_IMPLICIT;
	rtapi_u64 w2 = two_over_pi_at(e - 1);
	rtapi_u64 w1 = two_over_pi_at(e - 1 + 64);
	rtapi_u64 w0 = two_over_pi_at(e - 1 + 128);
	unsigned __int128 p0 = (unsigned __int128)M * w0;
	unsigned __int128 p1 = (unsigned __int128)M * w1;
	unsigned __int128 p2 = (unsigned __int128)M * w2;
	unsigned __int128 t, f;
	rtapi_u64 limb0, limb1, limb2, gh, gl;
	int q, n = 0, neg = 0;
	double hi, lo;

	/* P = M * W = sum of the three products; x * 2/pi mod 4 = P / 2^190 */
	limb0 = (rtapi_u64)p0;
	t = (unsigned __int128)(rtapi_u64)p1 + (rtapi_u64)(p0 >> 64);
	limb1 = (rtapi_u64)t;
	t = (unsigned __int128)(rtapi_u64)p2 + (rtapi_u64)(t >> 64) + (rtapi_u64)(p1 >> 64);
	limb2 = (rtapi_u64)t;
	q = (int)(limb2 >> 62);
	f = ((unsigned __int128)((limb2 << 2) | (limb1 >> 62)) << 64) | ((limb1 << 2) | (limb0 >> 62));
	if (f >> 127) {		/* fraction >= 1/2: round to the next quadrant */
		q++;
		f = ~f + 1;
		neg = 1;
	}
	if (f == 0) {
		r->hi = r->lo = 0.0;
		return q & 3;
	}
	while (!(f >> 127)) {	/* normalize; the fraction is never below 2^-70 */
		f <<= 1;
		n++;
	}
	gh = (rtapi_u64)(f >> 64);
	gl = (rtapi_u64)f;
	hi = (double)(gh >> 11) * rtm_pow2(-53 - n);		/* exact: 53 bits */
	lo = (double)((gh << 53) | (gl >> 11)) * rtm_pow2(-117 - n);
	*r = rtm_dd_mul(rtm_dd_make(hi, lo), pio2);
	if (neg)
		*r = rtm_dd_neg(*r);
	return q & 3;
}

/* x = q * pi/2 + r with |r| <= pi/4 (a hair more), r as a double-double; returns q mod 4.
 * x is finite. */
static int rem_pio2(double x, struct rtm_dd *r)
{
	double ax = rtapi_fabs(x), kd, t;
	struct rtm_dd a, b;
	int q;

	if (ax <= PI_4) {
		r->hi = x;
		r->lo = 0.0;
		return 0;
	}
	if (ax >= 0x1p20 * PIO2_1) {
		q = rem_pio2_large(ax, r);
		if (x < 0.0) {
			*r = rtm_dd_neg(*r);
			q = -q;
		}
		return q & 3;
	}
	kd = rtm_nearest(x * TWO_OVER_PI);
	t = x - kd * PIO2_1;			/* exact */
	a = rtm_two_sum(t, -(kd * PIO2_2));	/* kd * PIO2_2 exact */
	b = rtm_two_sum(a.hi, -(kd * PIO2_3));
	*r = rtm_fast_two_sum(b.hi, (a.lo + b.lo) - kd * PIO2_3T);
	return (int)kd & 3;
}

/* sin(r) for |r| <= pi/4 + tiny, as an unrounded double-double; Taylor through r^21. */
static struct rtm_dd sin_kernel(struct rtm_dd r)
{
	double x = r.hi, z = x * x, p;

	p = -1.0 / 39916800.0 + z * (1.0 / 6227020800.0 + z * (-1.0 / 1307674368000.0 +
	    z * (1.0 / 355687428096000.0 + z * (-1.0 / 121645100408832000.0 +
	    z * (1.0 / 51090942171709440000.0)))));
	p = -1.0 / 6.0 + z * (1.0 / 120.0 + z * (-1.0 / 5040.0 + z * (1.0 / 362880.0 + z * p)));
	return rtm_fast_two_sum(x, x * z * p + r.lo * (1.0 - 0.5 * z));
}

/* cos(r) likewise; Taylor through r^22, with 1 - r^2/2 kept exact. */
static struct rtm_dd cos_kernel(struct rtm_dd r)
{
	double x = r.hi, p, w;
	struct rtm_dd z = rtm_two_prod(x, x);
	double hz = 0.5 * z.hi, zz = z.hi;

	p = -1.0 / 3628800.0 + zz * (1.0 / 479001600.0 + zz * (-1.0 / 87178291200.0 +
	    zz * (1.0 / 20922789888000.0 + zz * (-1.0 / 6402373705728000.0 +
	    zz * (1.0 / 2432902008176640000.0 + zz * (-1.0 / 1124000727777607680000.0))))));
	p = 1.0 / 24.0 + zz * (-1.0 / 720.0 + zz * (1.0 / 40320.0 + zz * p));
	w = 1.0 - hz;
	return rtm_fast_two_sum(w, ((1.0 - w) - hz) + (zz * zz * p - 0.5 * z.lo - x * r.lo));
}

double rtapi_sin(double x)
{
	struct rtm_dd r, v;
	int q;

	if (!rtapi_isfinite(x))
		return x - x;
	if (rtapi_fabs(x) < 0x1p-26)
		return x;
	q = rem_pio2(x, &r);
	v = (q & 1) ? cos_kernel(r) : sin_kernel(r);
	return (q & 2) ? -v.hi : v.hi;
}

double rtapi_cos(double x)
{
	struct rtm_dd r, v;
	int q;

	if (!rtapi_isfinite(x))
		return x - x;
	if (rtapi_fabs(x) < 0x1p-27)
		return 1.0;
	q = rem_pio2(x, &r);
	v = (q & 1) ? sin_kernel(r) : cos_kernel(r);
	return ((q + 1) & 2) ? -v.hi : v.hi;
}

double rtapi_tan(double x)
{
	struct rtm_dd r, s, c;
	int q;

	if (!rtapi_isfinite(x))
		return x - x;
	if (rtapi_fabs(x) < 0x1p-27)
		return x;
	q = rem_pio2(x, &r);
	s = sin_kernel(r);
	c = cos_kernel(r);
	if (q & 1)
		return -rtm_dd_div(c, s).hi;
	return rtm_dd_div(s, c).hi;
}

/* atan(a) for a >= 0 finite, a double-double: atan(a) = pi/2 - atan(1/a) above 1, then
 * atan(a) = atan(c) + atan((a - c) / (1 + a c)) with c = j/16 nearest to a, leaving
 * |t| < 1/32 for a Taylor series through t^15. */
static struct rtm_dd atan_pos(struct rtm_dd a)
{
	struct rtm_dd t, num, den, res;
	double z, p, c;
	int j, inv = 0;

	if (a.hi > 0x1p60)	/* atan a = pi/2 - 1/a to the last bit */
		return rtm_dd_sub(pio2, rtm_dd_make(1.0 / a.hi, 0.0));
	if (a.hi > 1.0) {
		a = rtm_dd_div(rtm_dd_make(1.0, 0.0), a);
		inv = 1;
	}
	j = (int)(a.hi * 16.0 + 0.5);
	if (j == 0) {
		t = a;
	} else {
		c = j / 16.0;
		num = rtm_two_sum(a.hi - c, a.lo);	/* a.hi - c exact (Sterbenz) */
		den = rtm_dd_add(rtm_dd_make(1.0, 0.0), rtm_dd_mul_d(a, c));
		t = rtm_dd_div(num, den);
	}
	z = t.hi * t.hi;
	p = -1.0 / 3 + z * (1.0 / 5 + z * (-1.0 / 7 + z * (1.0 / 9 + z * (-1.0 / 11 +
	    z * (1.0 / 13 + z * (-1.0 / 15))))));
	res = rtm_fast_two_sum(t.hi, t.hi * z * p + t.lo * (1.0 - z));
	res = rtm_dd_add(atan_j16[j], res);
	if (inv)
		res = rtm_dd_sub(pio2, res);
	return res;
}

double rtapi_atan(double x)
{
	double r;

	if (rtapi_isnan(x) || rtapi_fabs(x) < 0x1p-27)
		return x + x * 0.0;	/* NaN; tiny x (keeps -0) */
	if (rtapi_isinf(x))
		r = pio2.hi;
	else
		r = atan_pos(rtm_dd_make(rtapi_fabs(x), 0.0)).hi;
	return x < 0.0 ? -r : r;
}

double rtapi_atan2(double y, double x)
{
	int xneg = (rtm_bits(x) & RTM_SIGN) != 0;
	int yneg = (rtm_bits(y) & RTM_SIGN) != 0;
	double ax = rtapi_fabs(x), ay = rtapi_fabs(y), r;
	int ex, ey;
	struct rtm_dd q, p, res;

	if (rtapi_isnan(x) || rtapi_isnan(y))
		return x + y;
	if (y == 0.0)
		return xneg ? (yneg ? -pi.hi : pi.hi) : y;
	if (x == 0.0 || (rtapi_isinf(y) && !rtapi_isinf(x)))
		return yneg ? -pio2.hi : pio2.hi;
	if (rtapi_isinf(x)) {
		if (rtapi_isinf(y))
			r = xneg ? 3.0 * PI_4 : PI_4;
		else
			r = xneg ? pi.hi : 0.0;
		return yneg ? -r : r;
	}
	ex = (int)(rtm_bits(ax) >> 52);
	ey = (int)(rtm_bits(ay) >> 52);
	if (ey - ex > 60) {			/* the angle is pi/2 to the last bit */
		res = pio2;
	} else if (ex - ey > 60) {		/* y/x is below 2^-60: atan(y/x) = y/x */
		res = rtm_dd_make(ay / ax, 0.0);
	} else {
		if (ex > 1023 + 900 || ey > 1023 + 900) {	/* keep the products finite */
			ax *= 0x1p-600;
			ay *= 0x1p-600;
		} else if (ex < 1023 - 900 || ey < 1023 - 900) {
			ax *= 0x1p600;
			ay *= 0x1p600;
		}
		q.hi = ay / ax;
		p = rtm_two_prod(q.hi, ax);
		q.lo = ((ay - p.hi) - p.lo) / ax;
		res = atan_pos(q);
	}
	if (xneg)
		res = rtm_dd_sub(pi, res);
	return yneg ? -res.hi : res.hi;
}

/* 1 - a^2 for 0 <= a <= 1, as a double-double without cancellation. */
static struct rtm_dd one_minus_sq(double a)
{
	struct rtm_dd p, s;

	if (a >= 0.5)		/* (1 - a) is exact, (1 + a) kept exact in two parts */
		return rtm_dd_mul(rtm_dd_make(1.0 - a, 0.0), rtm_two_sum(1.0, a));
	p = rtm_two_prod(a, a);
	s = rtm_two_sum(1.0, -p.hi);
	return rtm_fast_two_sum(s.hi, s.lo - p.lo);
}

double rtapi_asin(double x)
{
	double a = rtapi_fabs(x), r;

	if (rtapi_isnan(x))
		return x + x;
	if (a > 1.0)
		return __builtin_nan("");
	if (a < 0x1p-26)
		return x;
	if (a == 1.0)
		r = pio2.hi;
	else	/* asin a = atan(a / sqrt(1 - a^2)) */
		r = atan_pos(rtm_dd_div(rtm_dd_make(a, 0.0), rtm_dd_sqrt(one_minus_sq(a)))).hi;
	return x < 0.0 ? -r : r;
}

double rtapi_acos(double x)
{
	double a = rtapi_fabs(x);
	struct rtm_dd r;

	if (rtapi_isnan(x))
		return x + x;
	if (a > 1.0)
		return __builtin_nan("");
	if (a < 0x1p-60)
		return pio2.hi - x;
	if (a == 1.0)
		return x > 0.0 ? 0.0 : pi.hi;
	/* acos |x| = atan(sqrt(1 - x^2) / |x|); acos(-a) = pi - acos(a) */
	r = atan_pos(rtm_dd_div(rtm_dd_sqrt(one_minus_sq(a)), rtm_dd_make(a, 0.0)));
	if (x < 0.0)
		r = rtm_dd_sub(pi, r);
	return r.hi;
}
