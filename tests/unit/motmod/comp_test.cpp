// SPDX-License-Identifier: GPL-2.0-or-later
// Backlash and screw compensation (kernel/motion/comp.h): the table, its
// interpolation and the correction filter.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "comp.h"

namespace {

TEST(Comp, BacklashByDirection)
{
    auto t = std::make_unique<comp_table>();
    comp_table_clear(t.get());
    EXPECT_DOUBLE_EQ(comp_correction(t.get(), 0.2, 5.0, 1.0, 0.0), 0.1);
    EXPECT_DOUBLE_EQ(comp_correction(t.get(), 0.2, 5.0, -1.0, 0.1), -0.1);
    EXPECT_DOUBLE_EQ(comp_correction(t.get(), 0.2, 5.0, 0.0, -0.1), -0.1);  // kept at rest
}

TEST(Comp, TableInterpolatesAndExtendsFlat)
{
    auto t = std::make_unique<comp_table>();
    comp_table_clear(t.get());
    ASSERT_EQ(comp_table_add(t.get(), -10, 0.01, -0.02), COMP_ADD_OK);
    ASSERT_EQ(comp_table_add(t.get(), 0, -0.02, 0.02), COMP_ADD_OK);
    ASSERT_EQ(comp_table_add(t.get(), 10, 0.01, 0.04), COMP_ADD_OK);
    // the backlash is ignored once a table exists
    EXPECT_NEAR(comp_correction(t.get(), 1.0, 5.0, 1.0, 0), -0.005, 1e-15);
    EXPECT_NEAR(comp_correction(t.get(), 1.0, 5.0, -1.0, 0), 0.03, 1e-15);
    EXPECT_NEAR(comp_correction(t.get(), 1.0, -5.0, 1.0, 0), -0.005, 1e-15);
    EXPECT_NEAR(comp_correction(t.get(), 1.0, -5.0, -1.0, 0), 0.0, 1e-15);
    EXPECT_DOUBLE_EQ(comp_correction(t.get(), 0, 0.0, 1.0, 0), -0.02);   // at a point
    EXPECT_DOUBLE_EQ(comp_correction(t.get(), 0, 10.0, -1.0, 0), 0.04);
    EXPECT_DOUBLE_EQ(comp_correction(t.get(), 0, 1e6, 1.0, 0), 0.01);     // beyond: flat
    EXPECT_DOUBLE_EQ(comp_correction(t.get(), 0, -1e6, -1.0, 0), -0.02);
    EXPECT_DOUBLE_EQ(comp_correction(t.get(), 0, -1e6, 0.0, 0.5), 0.5);   // at rest: kept
}

TEST(Comp, TableRefusesDisorderOverflowAndNonFinite)
{
    auto t = std::make_unique<comp_table>();
    comp_table_clear(t.get());
    ASSERT_EQ(comp_table_add(t.get(), 1, 0, 0), COMP_ADD_OK);
    EXPECT_EQ(comp_table_add(t.get(), 1, 0, 0), COMP_ADD_ORDER);
    EXPECT_EQ(comp_table_add(t.get(), 0.5, 0, 0), COMP_ADD_ORDER);
    EXPECT_EQ(comp_table_add(t.get(), std::nan(""), 0, 0), COMP_ADD_NOT_FINITE);
    EXPECT_EQ(comp_table_add(t.get(), 2, std::numeric_limits<double>::infinity(), 0),
              COMP_ADD_NOT_FINITE);
    for (int i = 2; i <= MOTION_COMP_SIZE; ++i)
        ASSERT_EQ(comp_table_add(t.get(), i, 0, 0), COMP_ADD_OK) << i;
    EXPECT_EQ(t->count, MOTION_COMP_SIZE);
    EXPECT_EQ(comp_table_add(t.get(), 1000, 0, 0), COMP_ADD_FULL);
}

TEST(Comp, FilterRespectsItsLimitsAndArrives)
{
    double filt = 0, vel = 0, prev_v = 0, dt = 0.001;
    int steps = 0;
    for (; steps < 10000 && !(filt == 0.3 && vel == 0); ++steps) {
        comp_filter(0.3, &filt, &vel, 5.0, 50.0, dt);
        EXPECT_LE(std::fabs(vel), 5.0 + 1e-12);
        EXPECT_LE(std::fabs(vel - prev_v), 50.0 * dt + 1e-12);
        prev_v = vel;
    }
    EXPECT_EQ(filt, 0.3);
    EXPECT_LT(steps, 200);
    // no velocity allowed (feed hold): held where it is
    comp_filter(-0.3, &filt, &vel, 0.0, 50.0, dt);
    EXPECT_EQ(filt, 0.3);
}

}  // namespace
