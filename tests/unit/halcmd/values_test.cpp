// SPDX-License-Identifier: GPL-2.0-or-later
// values_test.cpp - parsing setp/sets values, formatting values for show/getp
// (RULINGS.md: shortest form that round-trips), type names, name patterns.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "values.hpp"

using namespace hal::halcmd;

TEST(ParseValue, BitAcceptsLinuxCncSpellingsInAnyCase)
{
    for (const char* t : {"1", "TRUE", "true", "True", "on", "ON", "yes", "Yes"}) {
        auto v = parse_value(HAL_BIT, t);
        ASSERT_TRUE(v) << t;
        EXPECT_TRUE(v->b);
    }
    for (const char* f : {"0", "FALSE", "false", "False", "off", "Off", "no", "NO"}) {
        auto v = parse_value(HAL_BIT, f);
        ASSERT_TRUE(v) << f;
        EXPECT_FALSE(v->b);
    }
}

TEST(ParseValue, BadBitSaysValueAndAcceptedForms)
{
    auto v = parse_value(HAL_BIT, "maybe");
    ASSERT_FALSE(v);
    EXPECT_EQ(v.error().message, "'maybe' is not a valid bit value (use 1/0, true/false, on/off or yes/no, in any case)");
    EXPECT_FALSE(parse_value(HAL_BIT, "2"));
    EXPECT_FALSE(parse_value(HAL_BIT, "tru"));
    EXPECT_FALSE(parse_value(HAL_BIT, ""));
}

TEST(ParseValue, S32DecimalAndHex)
{
    EXPECT_EQ(parse_value(HAL_S32, "-42")->s, -42);
    EXPECT_EQ(parse_value(HAL_S32, "+7")->s, 7);
    EXPECT_EQ(parse_value(HAL_S32, "0x1F")->s, 31);
    EXPECT_EQ(parse_value(HAL_S32, "010")->s, 10);   // decimal, not octal
    EXPECT_EQ(parse_value(HAL_S32, "2147483647")->s, 2147483647);
    EXPECT_EQ(parse_value(HAL_S32, "-2147483648")->s, -2147483647 - 1);
}

TEST(ParseValue, S32OutOfRangeOrGarbage)
{
    for (const char* bad : {"2147483648", "-2147483649", "1.5", "", "0x", "12abc", "- 1", "99999999999999999999"}) {
        auto v = parse_value(HAL_S32, bad);
        ASSERT_FALSE(v) << bad;
        EXPECT_NE(v.error().message.find("-2147483648 to 2147483647"), std::string::npos);
    }
}

TEST(ParseValue, U32RangeAndNoSign)
{
    EXPECT_EQ(parse_value(HAL_U32, "4294967295")->u, 4294967295u);
    EXPECT_EQ(parse_value(HAL_U32, "0xffffffff")->u, 4294967295u);
    auto v = parse_value(HAL_U32, "-1");
    ASSERT_FALSE(v);
    EXPECT_EQ(v.error().message, "'-1' is not a valid u32 value (use a decimal or 0x hex integer from 0 to 4294967295)");
    EXPECT_FALSE(parse_value(HAL_U32, "4294967296"));
}

TEST(ParseValue, FloatNeedsFullMatch)
{
    EXPECT_DOUBLE_EQ(parse_value(HAL_FLOAT, "2.5")->f, 2.5);
    EXPECT_DOUBLE_EQ(parse_value(HAL_FLOAT, "-1e-3")->f, -0.001);
    EXPECT_DOUBLE_EQ(parse_value(HAL_FLOAT, "7")->f, 7.0);
    for (const char* bad : {"", "1.5x", "abc", " 1", "1e999"}) {
        auto v = parse_value(HAL_FLOAT, bad);
        ASSERT_FALSE(v) << bad;
        EXPECT_NE(v.error().message.find("not a valid float value"), std::string::npos);
    }
}

// Issue 19, items 4 and 9: one rule for floats (finite values only), and a NUL
// inside the text no longer ends the number early.
TEST(ParseValue, FloatIsFiniteAndWhole)
{
    for (const char* bad : {"nan", "NAN", "-nan", "inf", "-inf", "infinity", "1e999", "-1e400",
                            "0x1p2000"}) {
        auto v = parse_value(HAL_FLOAT, bad);
        ASSERT_FALSE(v) << bad;
        EXPECT_EQ(v.error().message,
                  "'" + std::string(bad) + "' is not a valid float value (use a finite number such "
                  "as 2, -0.5, 1e-3 or 0x1p4; nan, inf and values beyond +-1.7976931348623157e308 "
                  "are refused)");
    }
    EXPECT_FALSE(parse_value(HAL_FLOAT, std::string_view("2\0" "5", 3)));
    EXPECT_DOUBLE_EQ(parse_value(HAL_FLOAT, "1.7976931348623157e308")->f, 1.7976931348623157e308);
    EXPECT_EQ(parse_value(HAL_FLOAT, "1e-999")->f, 0.0);  // underflow rounds, as strtod does
    EXPECT_DOUBLE_EQ(parse_value(HAL_FLOAT, "0x1p4")->f, 16.0);
}

TEST(FormatValue, BitsAndIntegers)
{
    hal_value v{};
    v.b = true;
    EXPECT_EQ(format_value(HAL_BIT, v), "TRUE");
    v.b = false;
    EXPECT_EQ(format_value(HAL_BIT, v), "FALSE");
    v.s = -5;
    EXPECT_EQ(format_value(HAL_S32, v), "-5");
    v.u = 4294967295u;
    EXPECT_EQ(format_value(HAL_U32, v), "4294967295");
}

TEST(FormatFloat, ShortFormsStayShort)
{
    EXPECT_EQ(format_float(2.5), "2.5");
    EXPECT_EQ(format_float(1.0), "1");
    EXPECT_EQ(format_float(0.001), "0.001");
    EXPECT_EQ(format_float(0.0), "0");
    EXPECT_EQ(format_float(-0.1), "-0.1");
    EXPECT_EQ(format_float(1e-7), "1e-07");
    EXPECT_EQ(format_float(123456.0), "123456");
}

TEST(FormatFloat, LongValuesRoundTrip)
{
    EXPECT_EQ(format_float(0.1234567), "0.1234567");
    EXPECT_EQ(format_float(1.0 / 3.0), "0.3333333333333333");
    EXPECT_EQ(format_float(1234567.0), "1234567");
    for (double d : {M_PI, 1e300, -2.2250738585072014e-308, 0.1 + 0.2, 123456789.123})
        EXPECT_EQ(std::strtod(format_float(d).c_str(), nullptr), d) << format_float(d);
}

TEST(TypeNames, RoundTrip)
{
    for (hal_type_t t : {HAL_BIT, HAL_S32, HAL_U32, HAL_FLOAT})
        EXPECT_EQ(parse_type_name(type_name(t)), t);
    EXPECT_FALSE(parse_type_name("int"));
    EXPECT_STREQ(pin_dir_name(HAL_IO), "I/O");
    EXPECT_STREQ(param_dir_name(HAL_RO), "RO");
}

TEST(NameMatches, NoPatternMatchesAll)
{
    EXPECT_TRUE(name_matches({}, "and2.0.in0"));
}

TEST(NameMatches, PrefixOrGlob)
{
    EXPECT_TRUE(name_matches({"and2"}, "and2.0.in0"));
    EXPECT_FALSE(name_matches({"or2"}, "and2.0.in0"));
    EXPECT_TRUE(name_matches({"*.in?"}, "and2.0.in0"));
    EXPECT_FALSE(name_matches({"*.out"}, "and2.0.in0"));
    EXPECT_TRUE(name_matches({"or2", "and2.[0-9].in1"}, "and2.3.in1"));
}
