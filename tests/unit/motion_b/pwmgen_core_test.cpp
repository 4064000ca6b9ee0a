// SPDX-License-Identifier: GPL-2.0-or-later
// pwmgen(9) (kernel/components/pwmgen_core.h): pwm-freq and duty rounding,
// limits, dither averages, PDM density.
#include <gtest/gtest.h>

#include "pwmgen_core.h"

namespace {

pwmgen_settings settings(double freq, bool dither = false, int type = 0)
{
    pwmgen_settings s{};
    s.scale = 1.0;
    s.max_dc = 1.0;
    s.pwm_freq = freq;
    s.dither = dither;
    s.output_type = type;
    return s;
}

int highs(pwmgen_pulse& p, const pwmgen_plan& plan, int n)
{
    int h = 0;
    for (int i = 0; i < n; i++)
        h += pwmgen_pulse_step(&p, &plan);
    return h;
}

TEST(Pwmgen, FrequencyRoundsToWholePeriodsWithoutDither)
{
    pwmgen_plan plan{};
    pwmgen_settings s = settings(3000);
    double dc = pwmgen_plan_update(&plan, &s, 0.5, true, 50000);
    EXPECT_EQ(plan.period_fp, 7 * PWMGEN_FP_ONE);
    EXPECT_DOUBLE_EQ(s.pwm_freq, 1e9 / (7 * 50000.0));
    EXPECT_DOUBLE_EQ(dc, 4.0 / 7.0);  // 3.5 periods rounds to 4
}

TEST(Pwmgen, FrequencyIsLimitedToHalfTheMakePulsesRate)
{
    pwmgen_plan plan{};
    pwmgen_settings s = settings(1e6);
    pwmgen_plan_update(&plan, &s, 0.5, true, 50000);
    EXPECT_DOUBLE_EQ(s.pwm_freq, 10000.0);
    EXPECT_EQ(plan.period_fp, 2 * PWMGEN_FP_ONE);
}

TEST(Pwmgen, DitherKeepsTheFrequencyAndAveragesTheDuty)
{
    pwmgen_plan plan{};
    pwmgen_settings s = settings(3000, true);
    double dc = pwmgen_plan_update(&plan, &s, 0.5, true, 50000);
    EXPECT_DOUBLE_EQ(s.pwm_freq, 3000.0);
    EXPECT_DOUBLE_EQ(dc, 0.5);
    pwmgen_pulse p{};
    int h = highs(p, plan, 20000);  // 3000 cycles of 6.67 periods
    EXPECT_NEAR(h / 20000.0, 0.5, 0.001);
}

TEST(Pwmgen, ExactCycleWithoutDither)
{
    pwmgen_plan plan{};
    pwmgen_settings s = settings(1000);
    pwmgen_plan_update(&plan, &s, 0.25, true, 50000);
    pwmgen_pulse p{};
    for (int cycle = 0; cycle < 3; cycle++)
        for (int i = 0; i < 20; i++)
            EXPECT_EQ(pwmgen_pulse_step(&p, &plan), i < 5) << cycle << " " << i;
}

TEST(Pwmgen, PdmDensityMatchesTheDuty)
{
    pwmgen_plan plan{};
    pwmgen_settings s = settings(0);
    pwmgen_plan_update(&plan, &s, 0.3, true, 50000);
    pwmgen_pulse p{};
    EXPECT_EQ(highs(p, plan, 1000), 300);
}

TEST(Pwmgen, LimitsAndOutputTypes)
{
    pwmgen_plan plan{};
    pwmgen_settings s = settings(1000);
    s.min_dc = 0.2;
    EXPECT_DOUBLE_EQ(pwmgen_plan_update(&plan, &s, -0.5, true, 50000), 0.2);  // type 0
    s = settings(1000, false, 1);
    s.max_dc = 0.8;
    EXPECT_DOUBLE_EQ(pwmgen_plan_update(&plan, &s, -5, true, 50000), -0.8);
    EXPECT_TRUE(plan.reverse);
    s.scale = 4;
    s.offset = 0.25;
    EXPECT_DOUBLE_EQ(pwmgen_plan_update(&plan, &s, 1, true, 50000), 0.5);
    EXPECT_DOUBLE_EQ(pwmgen_plan_update(&plan, &s, 1, false, 50000), 0.0);
    EXPECT_FALSE(plan.enabled);
    pwmgen_pulse p{};
    EXPECT_FALSE(pwmgen_pulse_step(&p, &plan));
    s.max_dc = 2.0;
    s.min_dc = -1.0;
    pwmgen_plan_update(&plan, &s, 1, true, 50000);
    EXPECT_DOUBLE_EQ(s.max_dc, 1.0);
    EXPECT_DOUBLE_EQ(s.min_dc, 0.0);
}

}  // namespace
