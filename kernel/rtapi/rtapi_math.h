/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_math.h - floating-point functions for realtime code (intro(3rtapi), "rtapi_math.h").
 * The kernel has no libm, so rtapi_math*.c implement everything themselves, in plain C,
 * for both flavors. Use it instead of <math.h> in realtime components, and call FP
 * code only from functions exported with uses_fp = 1.
 *
 * Names: every function is rtapi_<name>. When the includer has NOT included <math.h>
 * (glibc's _MATH_H is undefined; the kernel has no <math.h>), this header also defines
 * macros so that component code can write sin(x), atan2(y, x), isnan(x), ... Define
 * RTAPI_MATH_NO_MACROS before including it to get only the rtapi_ names. Do not include
 * <math.h> after this header in the same file (its declarations would be renamed).
 *
 * Accuracy, in units in the last place (ULP) from the correctly rounded result, as
 * tests/unit/rtapi/rtapi_math_test.cpp checks it over random and edge-case arguments
 * against glibc's long double functions rounded to double (results in the subnormal
 * range may be off by one more subnormal ULP):
 *   exact (0 ULP): fabs floor ceil trunc round rint copysign fmin fmax fmod sqrt
 *   <= 1 ULP: sin cos tan (every finite argument: full Payne-Hanek reduction), asin acos
 *             atan atan2 exp log log10 pow sinh cosh tanh hypot
 * Internally they work in double-double and round once, so most results are the
 * correctly rounded ones. fmod is exact by long division (up to ~2000 steps when the
 * exponents of x and y are far apart).
 * Special values (NaN, infinities, signed zeros) follow C99 Annex F. */
#ifndef RTAPI_MATH_H
#define RTAPI_MATH_H

#ifdef __cplusplus
extern "C" {
#endif

double rtapi_sin(double x);
double rtapi_cos(double x);
double rtapi_tan(double x);
double rtapi_asin(double x);
double rtapi_acos(double x);
double rtapi_atan(double x);
double rtapi_atan2(double y, double x);
double rtapi_sinh(double x);
double rtapi_cosh(double x);
double rtapi_tanh(double x);
double rtapi_exp(double x);
double rtapi_log(double x);
double rtapi_log10(double x);
double rtapi_pow(double x, double y);
double rtapi_sqrt(double x);
double rtapi_fabs(double x);
double rtapi_floor(double x);
double rtapi_ceil(double x);
double rtapi_fmod(double x, double y);
double rtapi_hypot(double x, double y);
double rtapi_round(double x);	/* halfway cases away from zero */
double rtapi_trunc(double x);
double rtapi_rint(double x);	/* halfway cases to even (default rounding mode) */
double rtapi_copysign(double x, double y);
double rtapi_fmin(double x, double y);
double rtapi_fmax(double x, double y);
int rtapi_isnan(double x);
int rtapi_isinf(double x);	/* nonzero for +-inf */
int rtapi_isfinite(double x);

#ifndef M_E
#define M_E		2.7182818284590452354	/* e */
#endif
#ifndef M_LOG2E
#define M_LOG2E		1.4426950408889634074	/* log_2 e */
#endif
#ifndef M_LOG10E
#define M_LOG10E	0.43429448190325182765	/* log_10 e */
#endif
#ifndef M_LN2
#define M_LN2		0.69314718055994530942	/* log_e 2 */
#endif
#ifndef M_LN10
#define M_LN10		2.30258509299404568402	/* log_e 10 */
#endif
#ifndef M_PI
#define M_PI		3.14159265358979323846	/* pi */
#endif
#ifndef M_PI_2
#define M_PI_2		1.57079632679489661923	/* pi/2 */
#endif
#ifndef M_PI_4
#define M_PI_4		0.78539816339744830962	/* pi/4 */
#endif
#ifndef M_1_PI
#define M_1_PI		0.31830988618379067154	/* 1/pi */
#endif
#ifndef M_2_PI
#define M_2_PI		0.63661977236758134308	/* 2/pi */
#endif
#ifndef M_2_SQRTPI
#define M_2_SQRTPI	1.12837916709551257390	/* 2/sqrt(pi) */
#endif
#ifndef M_SQRT2
#define M_SQRT2		1.41421356237309504880	/* sqrt(2) */
#endif
#ifndef M_SQRT1_2
#define M_SQRT1_2	0.70710678118654752440	/* 1/sqrt(2) */
#endif

#if !defined(_MATH_H) && !defined(RTAPI_MATH_NO_MACROS)
#define sin(x)		rtapi_sin(x)
#define cos(x)		rtapi_cos(x)
#define tan(x)		rtapi_tan(x)
#define asin(x)		rtapi_asin(x)
#define acos(x)		rtapi_acos(x)
#define atan(x)		rtapi_atan(x)
#define atan2(y, x)	rtapi_atan2(y, x)
#define sinh(x)		rtapi_sinh(x)
#define cosh(x)		rtapi_cosh(x)
#define tanh(x)		rtapi_tanh(x)
#define exp(x)		rtapi_exp(x)
#define log(x)		rtapi_log(x)
#define log10(x)	rtapi_log10(x)
#define pow(x, y)	rtapi_pow(x, y)
#define sqrt(x)		rtapi_sqrt(x)
#define fabs(x)		rtapi_fabs(x)
#define floor(x)	rtapi_floor(x)
#define ceil(x)		rtapi_ceil(x)
#define fmod(x, y)	rtapi_fmod(x, y)
#define hypot(x, y)	rtapi_hypot(x, y)
#define round(x)	rtapi_round(x)
#define trunc(x)	rtapi_trunc(x)
#define rint(x)		rtapi_rint(x)
#define copysign(x, y)	rtapi_copysign(x, y)
#define fmin(x, y)	rtapi_fmin(x, y)
#define fmax(x, y)	rtapi_fmax(x, y)
#define isnan(x)	rtapi_isnan(x)
#define isinf(x)	rtapi_isinf(x)
#define isfinite(x)	rtapi_isfinite(x)
#endif

#ifdef __cplusplus
}
#endif
#endif /* RTAPI_MATH_H */
