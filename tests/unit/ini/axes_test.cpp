// SPDX-License-Identifier: GPL-2.0-or-later
// ini/axes.hpp: the axis letters' order and the per-axis values of a status line.
#include <gtest/gtest.h>

#include <cmath>

#include "ini/axes.hpp"

using namespace hal::ini;

TEST(Axes, IndexAndLowerCase)
{
    EXPECT_EQ(axis_index('X'), 0);
    EXPECT_EQ(axis_index('c'), 5);
    EXPECT_EQ(axis_index('W'), 8);
    EXPECT_EQ(axis_index('Q'), -1);
    EXPECT_EQ(axis_index('\0'), -1);
    EXPECT_EQ(axis_lower(3), 'a');
}

TEST(Axes, ValuesByAxisFollowTheLetters)
{
    double v[AXIS_COUNT] = {9, 9, 9, 9, 9, 9, 9, 9, 9};
    values_by_axis("XZB", "1.5 -2 inf", v);
    EXPECT_EQ(v[0], 1.5);
    EXPECT_EQ(v[1], 9);    // Y not listed: kept
    EXPECT_EQ(v[2], -2);
    EXPECT_EQ(v[4], 0);    // not finite
    double w[AXIS_COUNT] = {};
    values_by_axis("XYZ", "4 oops 6", w);
    EXPECT_EQ(w[0], 4);
    EXPECT_EQ(w[1], 0);    // the first non-number ends it
    EXPECT_EQ(w[2], 0);
}
