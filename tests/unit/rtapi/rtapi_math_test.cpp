// SPDX-License-Identifier: GPL-2.0-or-later
// rtapi_math_test - rtapi_math.h against the C library: the ULP bounds promised in
// rtapi_math.h over random and edge-case arguments, and C99 special values.
// The reference is the long double function rounded to double, which is more
// accurate than glibc's double functions (sinh, tanh are 2 ULP off there).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rtapi_math.h"  // after <cmath>: no sin -> rtapi_sin macros here

namespace {

using F1 = double (*)(double);
using F2 = double (*)(double, double);

int64_t ordered(double x)
{
    int64_t i;
    std::memcpy(&i, &x, sizeof i);
    return i < 0 ? INT64_MIN - i : i;  // monotonic in x, -0 and +0 adjacent
}

// Distance in units in the last place; NaN only matches NaN.
int64_t ulps(double got, double want)
{
    if (std::isnan(got) || std::isnan(want))
        return std::isnan(got) && std::isnan(want) ? 0 : INT64_MAX;
    int64_t d = ordered(got) - ordered(want);
    return d < 0 ? -d : d;
}

// Allowed distance: one more subnormal ULP where the result is subnormal, since
// scaling into that range rounds a second time.
int64_t allowed(int64_t bound, double want)
{
    return (want != 0.0 && std::fabs(want) < 0x1p-1022) ? bound + 1 : bound;
}

std::mt19937_64 rng(20240611);

double uniform(double lo, double hi)
{
    return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// |x| spread evenly over binary exponents -emax..emax, random sign.
double log_spread(double emax)
{
    double v = std::exp2(uniform(-emax, emax));
    return (rng() & 1) ? -v : v;
}

std::vector<double> edge_cases()
{
    return {0.0,     -0.0,   1.0,    -1.0,    0.5,     -0.5,      2.0,    M_PI,
            -M_PI,   M_PI_2, M_PI_4, 1e-300,  -1e-300, 5e-324,    -5e-324, 2.2250738585072014e-308,
            1e-8,    1e6,    1e22,   1e300,   -1e300,  1.7976931348623157e308, 710.0, -745.0,
            0x1.fffffffffffffp-1, 0x1.0000000000001p0, 6381956970095103.0 * 0x1p797, 3.0, 10.0, 0.1,
            INFINITY, -INFINITY, NAN};
}

struct Case1 {
    const char* name;
    F1 ours;
    std::function<double(double)> ref;
    int64_t bound;
    std::vector<std::pair<double, double>> ranges;  // uniform ranges; {0, e} = log spread up to 2^e
};

void check_unary(const Case1& c)
{
    auto check = [&](double x) {
        double want = c.ref(x), got = c.ours(x);
        if (std::isnan(want) || std::isinf(want) || want == 0.0) {
            // special results: same class, same sign of zero/infinity
            EXPECT_TRUE((std::isnan(got) && std::isnan(want)) || std::memcmp(&got, &want, sizeof got) == 0)
                << c.name << "(" << x << ") = " << got << ", want " << want;
            return;
        }
        ASSERT_LE(ulps(got, want), allowed(c.bound, want))
            << c.name << "(" << std::hexfloat << x << ") = " << got << ", want " << want;
    };
    for (double x : edge_cases())
        check(x);
    for (auto [lo, hi] : c.ranges)
        for (int i = 0; i < 20000; i++)
            check(lo == 0.0 && hi > 2.0 ? log_spread(hi) : uniform(lo, hi));
}

TEST(RtapiMath, UnaryFunctionsStayWithinTheirUlpBounds)
{
    const std::vector<Case1> cases = {
        {"sin", rtapi_sin, [](double x) { return (double)sinl(x); }, 1, {{-10, 10}, {-1e6, 1e6}, {0, 1023}}},
        {"cos", rtapi_cos, [](double x) { return (double)cosl(x); }, 1, {{-10, 10}, {-1e6, 1e6}, {0, 1023}}},
        {"tan", rtapi_tan, [](double x) { return (double)tanl(x); }, 1, {{-10, 10}, {-1e6, 1e6}, {0, 1023}}},
        {"asin", rtapi_asin, [](double x) { return (double)asinl(x); }, 1, {{-1, 1}, {0.99, 1}, {0, 60}}},
        {"acos", rtapi_acos, [](double x) { return (double)acosl(x); }, 1, {{-1, 1}, {0.99, 1}, {-1, -0.99}, {0, 60}}},
        {"atan", rtapi_atan, [](double x) { return (double)atanl(x); }, 1, {{-10, 10}, {0, 1023}}},
        {"exp", rtapi_exp, [](double x) { return (double)expl(x); }, 1, {{-2, 2}, {-745, 710}}},
        {"log", rtapi_log, [](double x) { return (double)logl(x); }, 1, {{0.5, 2}, {0, 1074}, {0, 1023}}},
        {"log10", rtapi_log10, [](double x) { return (double)log10l(x); }, 1, {{0.5, 2}, {0, 1023}}},
        {"sinh", rtapi_sinh, [](double x) { return (double)sinhl(x); }, 1, {{-2, 2}, {-30, 30}, {-711, 711}}},
        {"cosh", rtapi_cosh, [](double x) { return (double)coshl(x); }, 1, {{-2, 2}, {-30, 30}, {-711, 711}}},
        {"tanh", rtapi_tanh, [](double x) { return (double)tanhl(x); }, 1, {{-1, 1}, {-30, 30}}},
        {"sqrt", rtapi_sqrt, [](double x) { return std::sqrt(x); }, 0, {{0, 1023}, {0, 1074}}},
        {"fabs", rtapi_fabs, [](double x) { return std::fabs(x); }, 0, {{0, 1023}}},
        {"floor", rtapi_floor, [](double x) { return std::floor(x); }, 0, {{-1e6, 1e6}, {-3, 3}, {0, 60}}},
        {"ceil", rtapi_ceil, [](double x) { return std::ceil(x); }, 0, {{-1e6, 1e6}, {-3, 3}, {0, 60}}},
        {"trunc", rtapi_trunc, [](double x) { return std::trunc(x); }, 0, {{-1e6, 1e6}, {-3, 3}, {0, 60}}},
        {"round", rtapi_round, [](double x) { return std::round(x); }, 0, {{-1e6, 1e6}, {-3, 3}, {0, 60}}},
        {"rint", rtapi_rint, [](double x) { return std::rint(x); }, 0, {{-1e6, 1e6}, {-3, 3}, {0, 60}}},
    };
    for (const auto& c : cases)
        check_unary(c);
}

TEST(RtapiMath, SpecialValuesFollowC99)
{
    EXPECT_TRUE(std::isnan(rtapi_sin(INFINITY)));
    EXPECT_TRUE(std::isnan(rtapi_cos(-INFINITY)));
    EXPECT_TRUE(std::isnan(rtapi_log(-1.0)));
    EXPECT_TRUE(std::isnan(rtapi_sqrt(-1.0)));
    EXPECT_TRUE(std::isnan(rtapi_asin(1.5)));
    EXPECT_TRUE(std::isnan(rtapi_acos(-1.5)));
    EXPECT_TRUE(std::isnan(rtapi_fmod(1.0, 0.0)));
    EXPECT_TRUE(std::isnan(rtapi_fmod(INFINITY, 1.0)));
    EXPECT_TRUE(std::signbit(rtapi_sin(-0.0)));
    EXPECT_TRUE(std::signbit(rtapi_tan(-0.0)));
    EXPECT_TRUE(std::signbit(rtapi_atan(-0.0)));
    EXPECT_TRUE(std::signbit(rtapi_floor(-0.0)));
    EXPECT_TRUE(std::signbit(rtapi_ceil(-0.5)));
    EXPECT_TRUE(std::signbit(rtapi_round(-0.3)));
    EXPECT_TRUE(std::signbit(rtapi_rint(-0.3)));
    EXPECT_EQ(rtapi_log(0.0), -INFINITY);
    EXPECT_EQ(rtapi_log10(0.0), -INFINITY);
    EXPECT_EQ(rtapi_log(INFINITY), INFINITY);
    EXPECT_EQ(rtapi_exp(-INFINITY), 0.0);
    EXPECT_EQ(rtapi_exp(INFINITY), INFINITY);
    EXPECT_EQ(rtapi_exp(1000.0), INFINITY);
    EXPECT_EQ(rtapi_exp(-1000.0), 0.0);
    EXPECT_EQ(rtapi_sinh(-INFINITY), -INFINITY);
    EXPECT_EQ(rtapi_cosh(-INFINITY), INFINITY);
    EXPECT_EQ(rtapi_tanh(-INFINITY), -1.0);
    EXPECT_EQ(rtapi_atan(INFINITY), M_PI_2);
    EXPECT_EQ(rtapi_log10(1000.0), 3.0);
    EXPECT_EQ(rtapi_exp(0.0), 1.0);
    EXPECT_EQ(rtapi_cos(0.0), 1.0);
    EXPECT_EQ(rtapi_hypot(INFINITY, NAN), INFINITY);
    EXPECT_TRUE(std::isnan(rtapi_hypot(1.0, NAN)));
    EXPECT_EQ(rtapi_hypot(3.0, 4.0), 5.0);
    EXPECT_EQ(rtapi_hypot(1e300, 1e300), std::hypot(1e300, 1e300));
    EXPECT_EQ(rtapi_hypot(3e-320, 4e-320), std::hypot(3e-320, 4e-320));
    EXPECT_TRUE(rtapi_isnan(NAN));
    EXPECT_FALSE(rtapi_isnan(INFINITY));
    EXPECT_TRUE(rtapi_isinf(-INFINITY));
    EXPECT_FALSE(rtapi_isinf(1e308));
    EXPECT_TRUE(rtapi_isfinite(1e308));
    EXPECT_FALSE(rtapi_isfinite(NAN));
    EXPECT_EQ(rtapi_copysign(2.0, -0.0), -2.0);
    EXPECT_EQ(rtapi_fmin(NAN, 1.0), 1.0);
    EXPECT_EQ(rtapi_fmax(1.0, NAN), 1.0);
    EXPECT_EQ(rtapi_fmin(-1.0, 2.0), -1.0);
    EXPECT_EQ(rtapi_fmax(-1.0, 2.0), 2.0);
    EXPECT_TRUE(std::signbit(rtapi_fmin(0.0, -0.0)));
    EXPECT_FALSE(std::signbit(rtapi_fmax(-0.0, 0.0)));
    EXPECT_EQ(rtapi_rint(2.5), 2.0);
    EXPECT_EQ(rtapi_rint(3.5), 4.0);
    EXPECT_EQ(rtapi_round(2.5), 3.0);
    EXPECT_EQ(rtapi_round(-2.5), -3.0);
}

TEST(RtapiMath, PowFollowsC99SpecialCases)
{
    const double xs[] = {0.0, -0.0, 1.0, -1.0, 2.0, -2.0, 0.5, -0.5, INFINITY, -INFINITY, NAN, 3.0, -3.0};
    const double ys[] = {0.0, -0.0, 1.0, -1.0, 2.0, -2.0, 3.0, -3.0, 0.5, -0.5, INFINITY, -INFINITY, NAN, 1e300, -1e300, 2.5};
    for (double x : xs) {
        for (double y : ys) {
            double want = std::pow(x, y), got = rtapi_pow(x, y);
            if (std::isnan(want))
                EXPECT_TRUE(std::isnan(got)) << "pow(" << x << ", " << y << ") = " << got;
            else
                EXPECT_EQ(std::memcmp(&got, &want, sizeof got), 0)
                    << "pow(" << x << ", " << y << ") = " << got << ", want " << want;
        }
    }
    EXPECT_EQ(rtapi_pow(2.0, 10.0), 1024.0);
    EXPECT_EQ(rtapi_pow(10.0, -2.0), std::pow(10.0, -2.0));
    EXPECT_EQ(rtapi_pow(-2.0, 3.0), -8.0);
    EXPECT_EQ(rtapi_pow(2.0, 1024.0), INFINITY);
    EXPECT_EQ(rtapi_pow(2.0, -1074.0), 5e-324);
    EXPECT_EQ(rtapi_pow(2.0, -1080.0), 0.0);
}

struct Case2 {
    const char* name;
    F2 ours;
    std::function<double(double, double)> ref;
    int64_t bound;
    double xlo, xhi, ylo, yhi;
    bool log_x;  // x spread over exponents up to 2^xhi
};

TEST(RtapiMath, BinaryFunctionsStayWithinTheirUlpBounds)
{
    const std::vector<Case2> cases = {
        {"atan2", rtapi_atan2, [](double y, double x) { return (double)atan2l(y, x); }, 1, -10, 10, -10, 10, false},
        {"atan2", rtapi_atan2, [](double y, double x) { return (double)atan2l(y, x); }, 1, 0, 1000, -1e300, 1e300, true},
        {"pow", rtapi_pow, [](double x, double y) { return (double)powl(x, y); }, 1, 0, 10, -300, 300, false},
        {"pow", rtapi_pow, [](double x, double y) { return (double)powl(x, y); }, 1, 0.9, 1.1, -5000, 5000, false},
        {"pow", rtapi_pow, [](double x, double y) { return (double)powl(x, y); }, 1, 0, 1000, -1, 1, true},
        {"pow", rtapi_pow, [](double x, double y) { return (double)powl(std::fabs(x), y); }, 1, -10, 10, -3, 3, false},
        {"hypot", rtapi_hypot, [](double x, double y) { return (double)hypotl(x, y); }, 1, -10, 10, -10, 10, false},
        {"hypot", rtapi_hypot, [](double x, double y) { return (double)hypotl(x, y); }, 1, 0, 1023, -1e300, 1e300, true},
        {"fmod", rtapi_fmod, [](double x, double y) { return std::fmod(x, y); }, 0, -1e10, 1e10, -10, 10, false},
        {"fmod", rtapi_fmod, [](double x, double y) { return std::fmod(x, y); }, 0, 0, 1074, -1e-300, 1e300, true},
    };
    for (const auto& c : cases) {
        for (int i = 0; i < 20000; i++) {
            double x = c.log_x ? log_spread(c.xhi) : uniform(c.xlo, c.xhi);
            double y = uniform(c.ylo, c.yhi);
            if (std::string(c.name) == "pow" && c.xlo < 0)
                x = std::fabs(x);
            double want = c.ref(x, y), got = c.ours(x, y);
            if (std::isinf(want) || want == 0.0 || std::isnan(want)) {
                EXPECT_TRUE((std::isnan(want) && std::isnan(got)) || got == want)
                    << c.name << "(" << x << ", " << y << ") = " << got << ", want " << want;
                continue;
            }
            ASSERT_LE(ulps(got, want), allowed(c.bound, want))
                << c.name << "(" << std::hexfloat << x << ", " << y << ") = " << got << ", want " << want;
        }
    }
}

TEST(RtapiMath, Atan2HandlesZerosAndInfinities)
{
    const double vs[] = {0.0, -0.0, 1.0, -1.0, INFINITY, -INFINITY, NAN, 1e-310, -1e308};
    for (double y : vs) {
        for (double x : vs) {
            double want = std::atan2(y, x), got = rtapi_atan2(y, x);
            if (std::isnan(want))
                EXPECT_TRUE(std::isnan(got));
            else
                EXPECT_LE(ulps(got, want), 1) << "atan2(" << y << ", " << x << ") = " << got << ", want " << want;
        }
    }
}

TEST(RtapiMath, ConstantsAreThoseOfMathH)
{
    EXPECT_EQ(M_PI, 3.14159265358979323846);
    EXPECT_EQ(M_SQRT2, std::sqrt(2.0));
    EXPECT_EQ(M_E, std::exp(1.0));
}

}  // namespace
