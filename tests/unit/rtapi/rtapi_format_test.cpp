// SPDX-License-Identifier: GPL-2.0-or-later
// rtapi_format_test - rtapi_snprintf against glibc's snprintf for many formats and
// values; also rtapi_div_u64, rtapi_string.h and rtapi_byteorder.h.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "rtapi.h"
#include "rtapi_byteorder.h"
#include "rtapi_string.h"

namespace {

#pragma GCC diagnostic ignored "-Wformat-nonliteral"
#pragma GCC diagnostic ignored "-Wformat-security"
#pragma GCC diagnostic ignored "-Wformat"  // some cases test what glibc warns about
#pragma GCC diagnostic ignored "-Wformat-overflow"
#pragma GCC diagnostic ignored "-Wformat-truncation"

template <typename... Args>
void expect_like_glibc(const char* fmt, Args... args)
{
    char ours[700], theirs[700];
    int n_ours = rtapi_snprintf(ours, sizeof ours, fmt, args...);
    int n_theirs = std::snprintf(theirs, sizeof theirs, fmt, args...);
    EXPECT_STREQ(ours, theirs) << "format \"" << fmt << "\"";
    EXPECT_EQ(n_ours, n_theirs) << "format \"" << fmt << "\"";
}

TEST(RtapiSnprintf, IntegersMatchGlibc)
{
    expect_like_glibc("%d %i %u %x %X %o %c %s %%", -5, 7, 3000000000u, 255, 255, 8, 'q', "str");
    expect_like_glibc("%5d|%-5d|%05d|%+d|% d|%.3d|%8.3d|%-8.3d|%08.3d", 42, 42, 42, 42, 42, 7, 7, 7, 7);
    expect_like_glibc("%ld %lld %lu %llx %zu %zd %hhd %hd %hhu", -1234567890123L, INT64_MIN, UINT64_MAX,
                      0xdeadbeefcafeULL, (size_t)123, (ssize_t)-5, 300, 70000, 300);
    expect_like_glibc("%#x %#o %#X %#o %#x %.0d|%.0x|%#.0o", 255, 8, 0, 0, 0, 0, 0, 0);
    expect_like_glibc("%d %d %u", INT32_MIN, INT32_MAX, UINT32_MAX);
    expect_like_glibc("%-+6d|%+-6d|% 05d|%#10x|%#-10o|", 3, -3, 12, 0xab, 8);
    expect_like_glibc("%lx %lX %lo %lu", (unsigned long)-1, 0xabcdefUL, 0777UL, 0UL);
}

TEST(RtapiSnprintf, StringsCharsPointersMatchGlibc)
{
    int x;
    expect_like_glibc("%10s|%-10s|%.2s|%*d|%-*d|%.*s|", "abc", "abc", "abc", 6, 1, 6, 1, 2, "abcdef");
    expect_like_glibc("%p %p %20p %-20p|", (void*)nullptr, (void*)&x, (void*)nullptr, (void*)&x);
    expect_like_glibc("%c|%5c|%-5c|", 'a', 'b', 'c');
    expect_like_glibc("%s", (const char*)nullptr);
    expect_like_glibc("no conversions at all");
    expect_like_glibc("");
}

TEST(RtapiSnprintf, FloatsMatchGlibc)
{
    const double vals[] = {0.0, 1.0, 0.5, 0.125, 0.375, 2.5, 3.5, 1.5, 0.1, 0.2, 0.3, 1e-5,
        1.23456789e-7, 123456.789, 9.9999995, 99.99, 999999.5, 1e15, 1e16, 1e17, 1e21, 1e22, 1e23,
        1.7976931348623157e308, 4.9406564584124654e-324, 2.2250738585072014e-308, 1e-300, 1e300,
        M_PI, M_E, 1.0 / 3.0, 2.0 / 3.0, 5e-5, 0.00001234, 123.456, 0.95, 0.05, 0.15, 0.25, 0.35,
        0.45, 1234567.0, 12345678.9, 0.000123456, 100, 1e6, 1e7, 9.5, 0.999999, 0.9999995, 1e-10,
        6.02214076e23, 273.15, 65536.0, 4294967296.0, 18446744073709551616.0, 9007199254740993.0,
        0.001, 0.0625};
    const char* fmts[] = {"%f", "%.0f", "%.1f", "%.2f", "%.3f", "%.10f", "%.17f", "%.20f", "%e", "%.0e",
        "%.1e", "%.3e", "%.10e", "%.16e", "%E", "%g", "%.0g", "%.1g", "%.2g", "%.3g", "%.10g", "%.17g",
        "%G", "%#g", "%#.0f", "%#.0e", "%+f", "% f", "%12.3f", "%-12.3f|", "%012.3f", "%+012.3e",
        "%015g", "%-15g|", "%#.3g", "%.30f", "%.40e", "%F"};
    for (double v : vals) {
        for (const char* f : fmts) {
            if (v == 999999.5 && std::strcmp(f, "%#g") == 0)
                continue;  // glibc prints "1.e+06"; C99 (and we) print "1.00000e+06"
            expect_like_glibc(f, v);
            expect_like_glibc(f, -v);
        }
    }
    expect_like_glibc("%f %e %g %F %E %G %5f %-8f| %08f %+f", INFINITY, -INFINITY, NAN, INFINITY, NAN,
                      -INFINITY, INFINITY, NAN, INFINITY, INFINITY);
    expect_like_glibc("%f %g", -0.0, -0.0);
}

TEST(RtapiSnprintf, RandomDoublesMatchGlibc)
{
    const char* fmts[] = {"%f", "%.3f", "%e", "%.12e", "%g", "%.15g", "%.17g", "%.0f", "%.25e"};
    std::mt19937_64 rng(7);
    for (int i = 0; i < 20000; i++) {
        uint64_t bits = rng();
        double v;
        std::memcpy(&v, &bits, sizeof v);
        if (!std::isfinite(v))
            continue;
        expect_like_glibc(fmts[i % 9], v);
        if (::testing::Test::HasFailure())
            return;
    }
}

TEST(RtapiSnprintf, TruncatesAndReturnsTheFullLength)
{
    char buf[4];
    EXPECT_EQ(rtapi_snprintf(buf, sizeof buf, "%d", 123456), 6);
    EXPECT_STREQ(buf, "123");
    EXPECT_EQ(rtapi_snprintf(nullptr, 0, "%s", "hello"), 5);
    buf[0] = 'x';
    EXPECT_EQ(rtapi_snprintf(buf, 1, "abc"), 3);
    EXPECT_EQ(buf[0], '\0');
}

TEST(RtapiSnprintf, CopiesUnknownConversionsAsWritten)
{
    char buf[32];
    rtapi_snprintf(buf, sizeof buf, "a%qb");
    EXPECT_STREQ(buf, "a%qb");
    rtapi_snprintf(buf, sizeof buf, "end%");
    EXPECT_STREQ(buf, "end%");
}

TEST(RtapiDivU64, DividesWithRemainder)
{
    __u32 rem = 0;
    EXPECT_EQ(rtapi_div_u64_rem(10000000007ULL, 1000u, &rem), 10000000ULL);
    EXPECT_EQ(rem, 7u);
    EXPECT_EQ(rtapi_div_u64(UINT64_MAX, 0xffffffffu), 0x100000001ULL);
    EXPECT_EQ(rtapi_div_s64(-10000000000LL, 3), -3333333333LL);
}

TEST(RtapiString, StrlcpyAlwaysTerminates)
{
    char buf[4];
    EXPECT_EQ(rtapi_strlcpy(buf, "abcdef", sizeof buf), 6u);
    EXPECT_STREQ(buf, "abc");
    EXPECT_EQ(rtapi_strlcpy(buf, "ab", sizeof buf), 2u);
    EXPECT_STREQ(buf, "ab");
    EXPECT_EQ(rtapi_strlcpy(buf, "xyz", 0), 3u);
    EXPECT_STREQ(buf, "ab");
}

TEST(RtapiString, StrtolDetectsBasesAndSaturates)
{
    char* end;
    EXPECT_EQ(rtapi_strtol("  -42xyz", &end, 0), -42);
    EXPECT_STREQ(end, "xyz");
    EXPECT_EQ(rtapi_strtol("0x1F", nullptr, 0), 31);
    EXPECT_EQ(rtapi_strtol("017", nullptr, 0), 15);
    EXPECT_EQ(rtapi_strtol("0x10", nullptr, 16), 16);
    EXPECT_EQ(rtapi_strtol("ff", nullptr, 16), 255);
    EXPECT_EQ(rtapi_strtol("+7", nullptr, 10), 7);
    EXPECT_EQ(rtapi_strtol("99999999999999999999", nullptr, 10), INT64_MAX);
    EXPECT_EQ(rtapi_strtol("-99999999999999999999", nullptr, 10), INT64_MIN);
    EXPECT_EQ(rtapi_strtol("-9223372036854775808", nullptr, 10), INT64_MIN);
    EXPECT_EQ(rtapi_strtoul("18446744073709551615", nullptr, 0), UINT64_MAX);
    EXPECT_EQ(rtapi_strtoul("18446744073709551616", nullptr, 0), UINT64_MAX);
    const char* s = "abc";
    EXPECT_EQ(rtapi_strtol(s, &end, 10), 0);
    EXPECT_EQ(end, s);
    EXPECT_EQ(rtapi_strtol("0x", &end, 0), 0);
    EXPECT_STREQ(end, "x");
}

TEST(RtapiByteorder, MatchesTheCompiler)
{
    uint32_t one = 1;
    bool little = *reinterpret_cast<unsigned char*>(&one) == 1;
    EXPECT_EQ(RTAPI_LITTLE_ENDIAN, little ? 1 : 0);
    EXPECT_EQ(RTAPI_BIG_ENDIAN, little ? 0 : 1);
    EXPECT_EQ(RTAPI_FLOAT_BIG_ENDIAN, little ? 0 : 1);
}

}  // namespace
