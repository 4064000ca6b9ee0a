// SPDX-License-Identifier: GPL-2.0-or-later
// halsampler/halstreamer: option parsing, output format (RULINGS.md), input lines.
#include <gtest/gtest.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "sample_format.hpp"
#include "sampler_options.hpp"
#include "stream_parse.hpp"

namespace {

// argv-like storage for the option parsers.
struct Args {
    std::vector<std::string> text;
    std::vector<char*> ptrs;
    Args(std::initializer_list<const char*> a) : text(a.begin(), a.end())
    {
        for (auto& s : text)
            ptrs.push_back(s.data());
    }
    std::span<char* const> span() const { return {ptrs.data(), ptrs.size()}; }
};

TEST(HalsamplerOptions, DefaultsReadFifoZeroForever)
{
    Args a{"halsampler"};
    auto o = hal::parse_sampler_options(a.span());
    ASSERT_TRUE(o);
    EXPECT_EQ(o->channel, 0);
    EXPECT_EQ(o->count, 0u);
    EXPECT_FALSE(o->tag);
    EXPECT_EQ(o->filename, "");
}

TEST(HalsamplerOptions, TakesSeparateAndAttachedValues)
{
    Args a{"halsampler", "-c", "2", "-n10", "-t", "out.txt"};
    auto o = hal::parse_sampler_options(a.span());
    ASSERT_TRUE(o);
    EXPECT_EQ(o->channel, 2);
    EXPECT_EQ(o->count, 10u);
    EXPECT_TRUE(o->tag);
    EXPECT_EQ(o->filename, "out.txt");
}

TEST(HalsamplerOptions, CombinesFlags)
{
    Args a{"halsampler", "-tn", "5"};
    auto o = hal::parse_sampler_options(a.span());
    ASSERT_TRUE(o);
    EXPECT_TRUE(o->tag);
    EXPECT_EQ(o->count, 5u);
}

TEST(HalsamplerOptions, RefusesBadValues)
{
    Args bad_chan{"halsampler", "-c", "8"};
    auto o = hal::parse_sampler_options(bad_chan.span());
    ASSERT_FALSE(o);
    EXPECT_EQ(o.error().message, "-c 8: CHAN must be a FIFO number 0..7");
    Args bad_count{"halsampler", "-n", "-1"};
    EXPECT_FALSE(hal::parse_sampler_options(bad_count.span()));
    Args junk{"halsampler", "-n", "5x"};
    EXPECT_FALSE(hal::parse_sampler_options(junk.span()));
    Args missing{"halsampler", "-c"};
    o = hal::parse_sampler_options(missing.span());
    ASSERT_FALSE(o);
    EXPECT_EQ(o.error().message, "option -c needs a value");
    Args unknown{"halsampler", "-x"};
    o = hal::parse_sampler_options(unknown.span());
    ASSERT_FALSE(o);
    EXPECT_EQ(o.error().message, "unknown option -x");
    Args two{"halsampler", "a", "b"};
    EXPECT_FALSE(hal::parse_sampler_options(two.span()));
}

TEST(HalsamplerOptions, DoubleDashEndsOptions)
{
    Args a{"halsampler", "--", "-file"};
    auto o = hal::parse_sampler_options(a.span());
    ASSERT_TRUE(o);
    EXPECT_EQ(o->filename, "-file");
}

TEST(HalsamplerFormat, EachValueIsFollowedByOneSpace)
{
    hal_fifo_value rec[6];
    rec[HAL_FIFO_REC_SAMPLE].s = 42;
    rec[HAL_FIFO_REC_FLAGS].u = 0;
    rec[2].f = 0.25;
    rec[3].u = 1;
    rec[4].s = -12;
    rec[5].u = 4000000000u;
    EXPECT_EQ(hal::format_sample("fbsu", rec, false), "0.250000 1 -12 4000000000 \n");
    EXPECT_EQ(hal::format_sample("fbsu", rec, true), "42 0.250000 1 -12 4000000000 \n");
}

TEST(HalsamplerFormat, NegativeSampleNumbersPrintSigned)
{
    hal_fifo_value rec[3];
    rec[HAL_FIFO_REC_SAMPLE].s = -3;
    rec[HAL_FIFO_REC_FLAGS].u = 0;
    rec[2].u = 0;
    EXPECT_EQ(hal::format_sample("b", rec, true), "-3 0 \n");
}

TEST(HalstreamerOptions, ChannelAndFile)
{
    Args a{"halstreamer", "-c1", "data.txt"};
    auto o = hal::parse_streamer_options(a.span());
    ASSERT_TRUE(o);
    EXPECT_EQ(o->channel, 1);
    EXPECT_EQ(o->filename, "data.txt");
    Args bad{"halstreamer", "-c", "x"};
    EXPECT_FALSE(hal::parse_streamer_options(bad.span()));
    Args unknown{"halstreamer", "-t"};
    EXPECT_FALSE(hal::parse_streamer_options(unknown.span()));
}

TEST(HalstreamerLine, ParsesEveryType)
{
    auto v = hal::parse_stream_line("ffbsu", " 1.5\t-2e3 1 -12 4294967295\r\n");
    ASSERT_TRUE(v);
    ASSERT_EQ(v->size(), 5u);
    EXPECT_DOUBLE_EQ((*v)[0].f, 1.5);
    EXPECT_DOUBLE_EQ((*v)[1].f, -2000.0);
    EXPECT_EQ((*v)[2].u, 1u);
    EXPECT_EQ((*v)[3].s, -12);
    EXPECT_EQ((*v)[4].u, 4294967295u);
}

TEST(HalstreamerLine, ReadsWhatHalsamplerWrites)
{
    hal_fifo_value rec[5];
    rec[0].s = 0;
    rec[1].u = 0;
    rec[2].f = -0.125;
    rec[3].u = 0;
    rec[4].s = 7;
    auto v = hal::parse_stream_line("fbs", hal::format_sample("fbs", rec, false));
    ASSERT_TRUE(v);
    EXPECT_DOUBLE_EQ((*v)[0].f, -0.125);
    EXPECT_EQ((*v)[2].s, 7);
}

TEST(HalstreamerLine, WrongNumberOfValuesIsNamed)
{
    auto v = hal::parse_stream_line("ffbs", "1 2 0\n");
    ASSERT_FALSE(v);
    EXPECT_EQ(v.error().message, "expected 4 values (cfg 'ffbs'), found 3");
}

TEST(HalstreamerLine, ExtraFieldsAreIgnored)
{
    auto v = hal::parse_stream_line("fb", "1.5 1 # a comment\n");
    ASSERT_TRUE(v);
    ASSERT_EQ(v->size(), 2u);
}

TEST(HalstreamerLine, BadValuesAreNamed)
{
    auto v = hal::parse_stream_line("fb", "1.0 2\n");
    ASSERT_FALSE(v);
    EXPECT_EQ(v.error().message, "value 2 '2' is not a valid bit (0 or 1)");
    v = hal::parse_stream_line("f", "abc");
    ASSERT_FALSE(v);
    EXPECT_EQ(v.error().message, "value 1 'abc' is not a valid float");
    EXPECT_FALSE(hal::parse_stream_line("s", "2147483648"));
    EXPECT_TRUE(hal::parse_stream_line("s", "-2147483648"));
    EXPECT_FALSE(hal::parse_stream_line("u", "-1"));
    EXPECT_FALSE(hal::parse_stream_line("u", "4294967296"));
    EXPECT_FALSE(hal::parse_stream_line("s", "12abc"));
    EXPECT_FALSE(hal::parse_stream_line("f", "1e999"));
}

TEST(HalstreamerLine, SixtyFourBitTypesTakeTheirFullRange)
{
    auto v = hal::parse_stream_line("lk", "-9223372036854775808 18446744073709551615\n");
    ASSERT_TRUE(v);
    EXPECT_EQ((*v)[0].s, INT64_MIN);
    EXPECT_EQ((*v)[1].u, UINT64_MAX);
    EXPECT_FALSE(hal::parse_stream_line("l", "9223372036854775808"));
    EXPECT_FALSE(hal::parse_stream_line("k", "-1"));
    EXPECT_FALSE(hal::parse_stream_line("k", "18446744073709551616"));
    auto e = hal::parse_stream_line("k", "x");
    ASSERT_FALSE(e);
    EXPECT_EQ(e.error().message, "value 1 'x' is not a valid u64");
}

TEST(HalsamplerFormat, SixtyFourBitValuesPrintInDecimal)
{
    hal_fifo_value rec[4];
    rec[HAL_FIFO_REC_SAMPLE].s = 0;
    rec[HAL_FIFO_REC_FLAGS].u = 0;
    rec[2].s = INT64_MIN;
    rec[3].u = UINT64_MAX;
    EXPECT_EQ(hal::format_sample("LK", rec, false), "-9223372036854775808 18446744073709551615 \n");
}

TEST(HalstreamerLine, BlankLinesAreRecognised)
{
    EXPECT_TRUE(hal::is_blank_line(" \t\r\n"));
    EXPECT_TRUE(hal::is_blank_line(""));
    EXPECT_FALSE(hal::is_blank_line(" 0\n"));
}

}  // namespace

namespace {

// What halsampler printed before issue 20 (and what its page documents): printf.
std::string printf_line(double v)
{
    char buf[400];
    std::snprintf(buf, sizeof(buf), "%f \n", v);
    return buf;
}

std::string fast_line(double v)
{
    hal_fifo_value rec[3];
    rec[HAL_FIFO_REC_SAMPLE].s = 0;
    rec[HAL_FIFO_REC_FLAGS].u = 0;
    rec[2].f = v;
    return hal::format_sample("f", rec, false);
}

}  // namespace

TEST(HalsamplerFormat, FloatsAreByteForBytePrintf)
{
    const double tricky[] = {0.0, -0.0, 1.0, -1.0, 0.5, 0.0000005, 0.0000015, 0.0000025,
                             -0.0000005, 0.00000049999999999999994, 0.0078125, 0.0234375,
                             1e-7, -1e-7, 1e-300, 4.9e-324, -4.9e-324, 2.2250738585072014e-308,
                             123456.7890125, 999999.9999995, 9999999.9999995, 0.1, 0.2, 0.3,
                             1.0 / 3, 2.0 / 3, 1e15, 1e16 + 2, 9007199254740993.0, 1e22, 1e23,
                             1.7976931348623157e308, -1.7976931348623157e308,
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::quiet_NaN(),
                             -std::numeric_limits<double>::quiet_NaN()};
    for (double v : tricky)
        EXPECT_EQ(fast_line(v), printf_line(v)) << "value bits " << std::hexfloat << v;
    // Ties at the sixth decimal that are exact in binary: k/2^n, rounded to even by printf.
    for (int k = -4096; k <= 4096; k++) {
        double v = k / 1048576.0;  // multiples of 2^-20
        EXPECT_EQ(fast_line(v), printf_line(v)) << std::hexfloat << v;
    }
    // Every tie in range: the binary fractions with 128 as denominator (v * 10^6 ends
    // in exactly .5 only for odd multiples of 1/128), and their neighbours.
    for (int j = -3000; j <= 3000; j++) {
        double v = j / 128.0;
        EXPECT_EQ(fast_line(v), printf_line(v)) << std::hexfloat << v;
        EXPECT_EQ(fast_line(std::nextafter(v, 1e9)), printf_line(std::nextafter(v, 1e9)));
        EXPECT_EQ(fast_line(std::nextafter(v, -1e9)), printf_line(std::nextafter(v, -1e9)));
    }
    // Both sides of the limit of the integer path (2^43) and of the 64-bit range.
    for (double v : {std::ldexp(1.0, 43), std::nextafter(std::ldexp(1.0, 43), 0.0),
                     std::ldexp(1.0, 44) + 0.5, 1.8e13, 1.9e13, 1e19, 123456789012.345678})
        EXPECT_EQ(fast_line(v), printf_line(v)) << std::hexfloat << v;
    // A fixed pseudo-random spread of magnitudes and bit patterns.
    std::mt19937_64 gen(20);
    for (int i = 0; i < 20000; i++) {
        uint64_t bits = gen();
        double v;
        std::memcpy(&v, &bits, sizeof(v));
        if (i % 2)
            v = std::ldexp(static_cast<double>(bits >> 11), static_cast<int>(gen() % 110) - 100);
        EXPECT_EQ(fast_line(v), printf_line(v)) << std::hexfloat << v;
    }
}

TEST(HalsamplerFormat, IntegersAreByteForBytePrintf)
{
    hal_fifo_value rec[6];
    rec[HAL_FIFO_REC_SAMPLE].s = INT32_MIN;
    rec[HAL_FIFO_REC_FLAGS].u = 0;
    rec[2].s = INT32_MIN;
    rec[3].u = UINT32_MAX;
    rec[4].s = 0;
    rec[5].u = 2;  // any nonzero bit prints 1
    EXPECT_EQ(hal::format_sample("susb", rec, true), "-2147483648 -2147483648 4294967295 0 1 \n");
}

TEST(HalstreamerLine, FastAndSlowParsingAgreeWithStrtod)
{
    // Spellings from_chars takes and those left to strtod/strtoll, all as before issue 20.
    const char* floats[] = {"0", "-0", "0.000000", "1", "-1.5", "3.14159265358979", "1e10", "-2E-3",
                            "0.1", "1.7976931348623157e308", "2.2250738585072014e-308",
                            "123456789012345678901234567890", ".5", "5.", "+2.5", "0x1p3", "inf",
                            "-Infinity", "nan", "1e-320"};
    for (const char* f : floats) {
        auto v = hal::parse_stream_line("f", f);
        char* end = nullptr;
        errno = 0;
        double want = std::strtod(f, &end);
        bool ok = *end == 0 && errno != ERANGE;
        ASSERT_EQ(static_cast<bool>(v), ok) << f;
        if (ok && !std::isnan(want)) {
            EXPECT_EQ(std::memcmp(&(*v)[0].f, &want, sizeof(want)), 0) << f;
        }
    }
    for (const char* f : {"1e400", "-1e400", "1.5x", "--1", "1e", "e5"})
        EXPECT_FALSE(hal::parse_stream_line("f", f)) << f;
    EXPECT_EQ((*hal::parse_stream_line("s", "+7"))[0].s, 7);
    EXPECT_EQ((*hal::parse_stream_line("s", "-2147483648"))[0].s, INT32_MIN);
    EXPECT_FALSE(hal::parse_stream_line("s", "2147483648"));
    EXPECT_EQ((*hal::parse_stream_line("u", "4294967295"))[0].u, UINT32_MAX);
    EXPECT_FALSE(hal::parse_stream_line("u", "4294967296"));
    EXPECT_FALSE(hal::parse_stream_line("u", "-1"));
    EXPECT_EQ((*hal::parse_stream_line("L", "-9223372036854775808"))[0].s, INT64_MIN);
    EXPECT_FALSE(hal::parse_stream_line("L", "9223372036854775808"));
    EXPECT_EQ((*hal::parse_stream_line("K", "18446744073709551615"))[0].u, UINT64_MAX);
    EXPECT_FALSE(hal::parse_stream_line("K", "18446744073709551616"));
}
