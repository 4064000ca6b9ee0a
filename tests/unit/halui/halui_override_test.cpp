// Override knob arithmetic (user/halui/halui_override.cpp): counts, count-enable,
// direct value, increase/decrease/reset edges, clamps; time is an input.
#include <gtest/gtest.h>

#include "halui_override.hpp"

using namespace hal::halui;

TEST(HaluiOverride, CountsStepFromTheCurrentValue)
{
    OverrideKnob k(0, 1.5, true);
    OverrideIn in;
    EXPECT_FALSE(k.update(in, 1.0, 0));   // the first cycle records the pins
    in.counts = 3;
    auto v = k.update(in, 1.0, 0.02);
    ASSERT_TRUE(v);
    EXPECT_DOUBLE_EQ(*v, 1.3);
    // task has not reported 1.3 yet: the next step builds on what was sent
    in.counts = 4;
    v = k.update(in, 1.0, 0.04);
    ASSERT_TRUE(v);
    EXPECT_DOUBLE_EQ(*v, 1.4);
    EXPECT_FALSE(k.update(in, 1.4, 0.06));   // nothing moved
    in.counts = 2;
    v = k.update(in, 1.4, 0.08);
    ASSERT_TRUE(v);
    EXPECT_DOUBLE_EQ(*v, 1.2);
}

TEST(HaluiOverride, SentValueIsForgottenOnceReportedOrAfterHold)
{
    OverrideKnob k(0, 2, true);
    OverrideIn in;
    k.update(in, 1.0, 0);
    in.counts = 1;
    EXPECT_DOUBLE_EQ(*k.update(in, 1.0, 0.0), 1.1);
    // task refused it and still reports 1.0: after HOLD_S the status wins again
    in.counts = 2;
    EXPECT_DOUBLE_EQ(*k.update(in, 1.0, OverrideKnob::HOLD_S + 0.01), 1.1);
    // reported: the status is the base
    in.counts = 3;
    EXPECT_DOUBLE_EQ(*k.update(in, 0.7, OverrideKnob::HOLD_S + 0.02 + OverrideKnob::HOLD_S), 0.8);
}

TEST(HaluiOverride, CountEnableFalseAbsorbsCounts)
{
    OverrideKnob k(0, 2, true);
    OverrideIn in;
    k.update(in, 1.0, 0);
    in.count_enable = false;
    in.counts = 50;
    EXPECT_FALSE(k.update(in, 1.0, 1));
    in.count_enable = true;
    EXPECT_FALSE(k.update(in, 1.0, 2));   // the 50 counts are gone
    in.counts = 51;
    EXPECT_DOUBLE_EQ(*k.update(in, 1.0, 3), 1.1);
}

TEST(HaluiOverride, DirectValue)
{
    OverrideKnob k(0, 1.5, true);
    OverrideIn in;
    in.direct_value = true;
    in.scale = 0.01;
    k.update(in, 1.0, 0);
    in.counts = 75;
    EXPECT_DOUBLE_EQ(*k.update(in, 1.0, 1), 0.75);
    in.counts = 500;   // clamped
    EXPECT_DOUBLE_EQ(*k.update(in, 0.75, 2), 1.5);
    in.counts = -20;
    EXPECT_DOUBLE_EQ(*k.update(in, 1.5, 3), 0.0);
}

TEST(HaluiOverride, IncreaseDecreaseResetOnRisingEdges)
{
    OverrideKnob k(0.5, 1.2, true);
    OverrideIn in;
    k.update(in, 1.0, 0);
    in.increase = true;
    EXPECT_DOUBLE_EQ(*k.update(in, 1.0, 1), 1.1);
    EXPECT_FALSE(k.update(in, 1.1, 2));   // held: once
    in.increase = false;
    k.update(in, 1.1, 3);
    in.increase = true;
    EXPECT_DOUBLE_EQ(*k.update(in, 1.1, 4), 1.2);   // clamped at the maximum
    in.increase = false;
    in.decrease = true;
    in.scale = 1;
    EXPECT_DOUBLE_EQ(*k.update(in, 1.2, 5), 0.5);   // clamped at the minimum
    in.decrease = false;
    in.reset = true;
    EXPECT_DOUBLE_EQ(*k.update(in, 0.5, 6), 1.0);
}

TEST(HaluiOverride, NoResetPinNoReset)
{
    OverrideKnob k(0, 100, false);
    OverrideIn in;
    k.update(in, 30, 0);
    in.reset = true;
    EXPECT_FALSE(k.update(in, 30, 1));
}

TEST(HaluiOverride, CountsWrapLikeAnEncoder)
{
    OverrideKnob k(-1e12, 1e12, false);
    OverrideIn in;
    in.counts = 2147483647;
    in.scale = 1;
    k.update(in, 0, 0);
    in.counts = -2147483647 - 1;
    EXPECT_DOUBLE_EQ(*k.update(in, 0, 1), 1.0);   // one step up through the wrap
    in.counts = 2147483646;
    EXPECT_DOUBLE_EQ(*k.update(in, 1, 2), -1.0);   // two steps back
}
