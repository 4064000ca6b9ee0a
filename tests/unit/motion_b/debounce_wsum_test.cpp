// SPDX-License-Identifier: GPL-2.0-or-later
// debounce(9) filter (debounce_core.h) and weighted_sum(9) (weighted_sum_core.h).
#include <gtest/gtest.h>

#include "debounce_core.h"
#include "weighted_sum_core.h"

namespace {

TEST(Debounce, RejectsGlitchesUpToDelayPeriods)
{
    for (int delay = 0; delay < 6; delay++) {
        for (int len = 1; len <= 8; len++) {
            debounce_filter f{};
            bool passed = false;
            for (int i = 0; i < len; i++)
                passed |= debounce_step(&f, true, delay);
            for (int i = 0; i < 10; i++)
                debounce_step(&f, false, delay);
            EXPECT_EQ(passed, len > delay) << "delay " << delay << " glitch " << len;
            EXPECT_FALSE(f.out);
        }
    }
}

TEST(Debounce, LoweringDelayTakesEffectAtOnce)
{
    debounce_filter f{};
    for (int i = 0; i < 10; i++)
        debounce_step(&f, true, 8);
    EXPECT_TRUE(f.out);
    EXPECT_FALSE(debounce_step(&f, false, 0));
    EXPECT_TRUE(debounce_step(&f, true, -3));  // negative delay counts as 0
}

TEST(WeightedSum, AddsWeightsOfTrueBitsToTheOffset)
{
    bool bits[4] = {true, false, true, true};
    rtapi_s32 w[4] = {1, 2, 4, 8};
    EXPECT_EQ(wsum_compute(bits, w, 4, 0), 13);
    rtapi_s32 w2[4] = {10, -3, -100, 7};
    EXPECT_EQ(wsum_compute(bits, w2, 4, 5), 10 - 100 + 7 + 5);
    rtapi_s32 big[4] = {0x7fffffff, 0, 1, 0};
    EXPECT_EQ(wsum_compute(bits, big, 4, 0), (rtapi_s32)0x80000000u);  // wraps, no UB
}

}  // namespace
