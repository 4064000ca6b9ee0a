// SPDX-License-Identifier: GPL-2.0-or-later
// hal/numbers.hpp: a whole word as a number (bus commands, emcrsh, tool tables).
#include <gtest/gtest.h>

#include "hal/numbers.hpp"

TEST(Numbers, Finite)
{
    double v = 7;
    EXPECT_TRUE(hal::parse_finite("-1.5e2", v));
    EXPECT_EQ(v, -150);
    for (const char* bad : {"", "1.5x", " x", "nan", "inf", "1e999"})
        EXPECT_FALSE(hal::parse_finite(bad, v)) << bad;
    EXPECT_EQ(v, -150);   // unchanged by a refusal
}

TEST(Numbers, IntegerInRange)
{
    long n = 3;
    EXPECT_TRUE(hal::parse_integer("-42", n));
    EXPECT_EQ(n, -42);
    EXPECT_FALSE(hal::parse_integer("12", n, 0, 10));
    EXPECT_FALSE(hal::parse_integer("1.0", n));
    EXPECT_FALSE(hal::parse_integer("", n));
    EXPECT_FALSE(hal::parse_integer("99999999999999999999", n));
    EXPECT_EQ(n, -42);
}
