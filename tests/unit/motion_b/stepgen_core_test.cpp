// SPDX-License-Identifier: GPL-2.0-or-later
// stepgen(9) pulse maker (kernel/components/stepgen_core.h): the phase tables,
// user step types, rounding of ns to periods, and the timing of single steps.
#include <gtest/gtest.h>

#include <vector>

#include "stepgen_core.h"

namespace {

// Runs a generator at a constant addval for n periods; returns the out[0..k) levels.
struct Gen {
    stepgen_pulse p{};
    stepgen_timing t{1, 1, 1, 1, 1};
    int type;
    const stepgen_pattern* pat;
    explicit Gen(int ty, const stepgen_pattern* pt = nullptr) : type(ty), pat(pt)
    {
        stepgen_pulse_init(&p);
        if (!pat)
            pat = &stepgen_builtin_patterns[ty < 2 ? 2 : ty];
    }
    int step(double steps_per_period, bool enable = true)
    {
        p.addval = (rtapi_u64)(rtapi_s64)(steps_per_period * STEPGEN_ONE_STEP);
        return stepgen_pulse_step(&p, type, pat, &t, enable);
    }
    int bits() const
    {
        int b = 0;
        for (int i = 0; i < STEPGEN_MAX_PHASES; i++)
            b |= p.out[i] << i;
        return b;
    }
};

TEST(StepgenPatterns, QuadratureHasALeadingBForward)
{
    Gen g(2);
    std::vector<int> seen;
    for (int i = 0; i < 5; i++) {
        g.step(1.0);
        seen.push_back(g.bits());
    }
    // state 0 is A alone; forward: A+B, B, none, A: A rises before B.
    EXPECT_EQ(seen, (std::vector<int>{3, 2, 0, 1, 3}));
}

TEST(StepgenPatterns, EveryBuiltinTypeCyclesThroughItsTableBothWays)
{
    for (int type = 2; type <= 14; type++) {
        const stepgen_pattern& pat = stepgen_builtin_patterns[type];
        Gen fwd(type), rev(type);
        for (int i = 1; i <= 2 * pat.len; i++) {
            fwd.step(1.0);
            rev.step(-1.0);
            EXPECT_EQ(fwd.bits(), pat.bits[i % pat.len]) << "type " << type << " step " << i;
            EXPECT_EQ(rev.bits(), pat.bits[(pat.len - i % pat.len) % pat.len])
                << "type " << type << " step " << i;
        }
    }
}

TEST(StepgenPatterns, CycleLengthsAndPhaseCountsMatchThePage)
{
    const int len[15] = {0, 0, 4, 3, 6, 4, 4, 4, 4, 8, 8, 5, 5, 10, 10};
    const int phases[15] = {0, 0, 2, 3, 3, 4, 4, 4, 4, 4, 4, 5, 5, 5, 5};
    for (int type = 2; type <= 14; type++) {
        EXPECT_EQ(stepgen_builtin_patterns[type].len, len[type]) << type;
        EXPECT_EQ(stepgen_builtin_patterns[type].phases, phases[type]) << type;
        int used = 0;
        for (int i = 0; i < len[type]; i++)
            used |= stepgen_builtin_patterns[type].bits[i];
        EXPECT_EQ(used, (1 << phases[type]) - 1) << "type " << type << " uses every phase";
    }
    // Three phase full step: only one phase at a time, A then B then C.
    EXPECT_EQ(stepgen_builtin_patterns[3].bits[0], 1);
    EXPECT_EQ(stepgen_builtin_patterns[3].bits[1], 2);
    EXPECT_EQ(stepgen_builtin_patterns[3].bits[2], 4);
}

TEST(StepgenUserType, TakesEntriesUpToTheFirstNegativeOne)
{
    int entries[10] = {1, 2, 4, 8, -1, -1, -1, -1, -1, -1};
    stepgen_pattern pat{};
    int bad = -1;
    ASSERT_EQ(stepgen_user_pattern(entries, 10, &pat, &bad), 0);
    EXPECT_EQ(pat.len, 4);
    EXPECT_EQ(pat.phases, 4);
}

TEST(StepgenUserType, RefusesASixthPhaseAndAnEmptyTable)
{
    int entries[10] = {1, 2, 33, -1, -1, -1, -1, -1, -1, -1};
    stepgen_pattern pat{};
    int bad = -1;
    EXPECT_EQ(stepgen_user_pattern(entries, 10, &pat, &bad), -EINVAL);
    EXPECT_EQ(bad, 2);
    int none[10] = {-1, -1, -1, -1, -1, -1, -1, -1, -1, -1};
    EXPECT_EQ(stepgen_user_pattern(none, 10, &pat, &bad), -ENOENT);
}

TEST(StepgenTiming, NanosecondsRoundUpToWholePeriods)
{
    EXPECT_EQ(stepgen_ns_to_periods(0, 25000), 0u);
    EXPECT_EQ(stepgen_ns_to_periods(1, 25000), 1u);
    EXPECT_EQ(stepgen_ns_to_periods(25000, 25000), 1u);
    EXPECT_EQ(stepgen_ns_to_periods(25001, 25000), 2u);
    EXPECT_EQ(stepgen_ns_to_periods(20000, 16000), 2u);  // the page's 16 us example
    EXPECT_EQ(stepgen_ns_to_periods(0xffffffffu, 1), STEPGEN_TIMER_MAX);
}

TEST(StepgenTiming, PeriodsPerStepDependOnTheType)
{
    stepgen_timing t{3, 2, 1, 1, 1};
    EXPECT_EQ(stepgen_periods_per_step(0, &t), 5u);
    EXPECT_EQ(stepgen_periods_per_step(1, &t), 5u);
    EXPECT_EQ(stepgen_periods_per_step(2, &t), 3u);
    stepgen_timing zero{0, 0, 0, 0, 0};
    EXPECT_EQ(stepgen_periods_per_step(0, &zero), 1u);
}

TEST(StepgenPulses, StepPinIsHighForSteplenPeriods)
{
    Gen g(0);
    g.t = {3, 2, 1, 1, 1};
    std::vector<int> step;
    for (int i = 0; i < 12; i++) {
        g.step(i == 0 ? 0.5 : 0.0);  // half a step from the start: one step
        step.push_back(g.p.out[0]);
    }
    EXPECT_EQ(step, (std::vector<int>{1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
    EXPECT_EQ(g.p.rawcount, 1);
}

TEST(StepgenPulses, ReversalWaitsForDirholdThenDirsetup)
{
    Gen g(0);
    g.t = {1, 1, 1, 2, 0};  // dirsetup 1, dirhold 2
    g.step(0.5);            // forward step in period 0
    EXPECT_TRUE(g.p.out[0]);
    std::vector<int> step, dir;
    for (int i = 0; i < 6; i++) {
        g.step(i == 0 ? -1.0 : 0.0);  // back one step
        step.push_back(g.p.out[0]);
        dir.push_back(g.p.out[1]);
    }
    // fall in period 1, dir changes 2 later (period 3), step 1 after that (period 4)
    EXPECT_EQ(step, (std::vector<int>{0, 0, 0, 1, 0, 0}));
    EXPECT_EQ(dir, (std::vector<int>{0, 0, 1, 1, 1, 1}));
    EXPECT_EQ(g.p.rawcount, 0);
}

TEST(StepgenPulses, DirFollowsTheRateSoTheFirstReverseStepIsNotDelayed)
{
    Gen g(0);  // dirsetup 1, dirhold 1
    std::vector<int> step, dir;
    for (int i = 0; i < 7; i++) {
        g.step(-0.25);  // backward at a quarter step per period from the start
        step.push_back(g.p.out[0]);
        dir.push_back(g.p.out[1]);
    }
    // dir turns in period 0, when the rate goes negative; the accumulator crosses the
    // half-step point in period 2 and the step comes in that period, as in LinuxCNC
    // (it used to wait for dirsetup from there: period 3)
    EXPECT_EQ(dir, (std::vector<int>{1, 1, 1, 1, 1, 1, 1}));
    EXPECT_EQ(step, (std::vector<int>{0, 0, 1, 0, 0, 0, 1}));
    EXPECT_EQ(g.p.rawcount, -2);
}

TEST(StepgenPulses, DirDoesNotTurnEarlyWhileAStepIsDue)
{
    Gen g(0);
    g.t = {3, 3, 1, 1, 0};  // 6 periods per step
    EXPECT_EQ(g.step(0.5), 1);   // forward step; the next forward one is held
    EXPECT_EQ(g.step(1.0), 0);   // due now, held by steplen + stepspace
    for (int i = 0; i < 3; i++) {
        g.step(-0.1);            // the rate reverses while the forward step is due
        EXPECT_FALSE(g.p.out[1]) << "period " << i;
    }
}

TEST(StepgenPulses, TimingLimitsHoldThePositionWithinOneStep)
{
    Gen g(0);
    g.t = {2, 2, 1, 1, 1};  // 4 periods per step; one step per period is asked for
    int steps = 0;
    for (int i = 0; i < 40; i++) {
        steps += g.step(1.0);
        rtapi_s64 ahead = (rtapi_s64)g.p.accum - STEPGEN_HALF_STEP - (rtapi_s64)g.p.rawcount * STEPGEN_ONE_STEP;
        EXPECT_LT(ahead, 2 * STEPGEN_ONE_STEP) << "period " << i;
    }
    EXPECT_EQ(steps, 10);  // steps at periods 0, 4, ... 36
}

TEST(StepgenPulses, StateTypesReverseAfterSteplenPlusDirdelay)
{
    Gen g(2);
    g.t = {1, 0, 0, 0, 2};
    EXPECT_EQ(g.step(0.5), 1);   // forward in period 0
    EXPECT_EQ(g.step(-1.0), 0);  // one period later: 1 < steplen + dirdelay
    EXPECT_EQ(g.step(0.0), 0);
    EXPECT_EQ(g.step(0.0), -1);  // three periods after the forward step
}

TEST(StepgenPulses, DisabledMakesNoSteps)
{
    Gen g(0);
    for (int i = 0; i < 10; i++)
        EXPECT_EQ(g.step(1.0, false), 0);
    EXPECT_EQ(g.p.rawcount, 0);
}

TEST(StepgenPulses, StepspaceZeroStepsEveryPeriod)
{
    Gen g(0);
    g.t = {1, 0, 0, 0, 0};
    int steps = 0;
    for (int i = 0; i < 10; i++) {
        steps += g.step(1.0);
        EXPECT_TRUE(g.p.out[0]);
    }
    EXPECT_EQ(steps, 10);
}

}  // namespace
