// SPDX-License-Identifier: GPL-2.0-or-later
// stepgen(9) control loops (kernel/components/stepgen_loop.h): the position loop
// makes trapezoids within maxvel/maxaccel without overshoot; the velocity loop
// ramps; the step-rate limit and addval conversions.
#include <gtest/gtest.h>

#include <cmath>

#include "stepgen_loop.h"

namespace {

constexpr double kT = 0.001;  // 1 ms update period

// Simulates the position loop on an ideal integrator; returns the peak position,
// and checks the limits on every period.
double run_move(double target, double vmax, double amax, int periods, double* final_pos)
{
    stepgen_loop l{};
    double pos = 0.0, peak = 0.0;
    for (int i = 0; i < periods; i++) {
        double v = stepgen_position_loop(&l, target, pos, vmax, amax, kT);
        EXPECT_LE(std::fabs(v), vmax * (1 + 1e-12)) << "period " << i;
        EXPECT_LE(std::fabs(v - l.vel), amax * kT * (1 + 1e-9)) << "period " << i;
        l.vel = v;
        pos += v * kT;
        peak = std::max(peak, pos);
    }
    *final_pos = pos;
    return peak;
}

TEST(StepgenLoop, JumpBecomesATrapezoidWithoutOvershoot)
{
    double fin;
    double peak = run_move(10.0, 20.0, 100.0, 2000, &fin);
    EXPECT_LE(peak, 10.0 + 1e-12);
    EXPECT_NEAR(fin, 10.0, 1e-9);
}

TEST(StepgenLoop, ShortMovesAreTrianglesWithoutOvershoot)
{
    for (double target : {1e-6, 0.001, 0.05, 0.3}) {
        double fin;
        double peak = run_move(target, 20.0, 100.0, 2000, &fin);
        EXPECT_LE(peak, target * (1 + 1e-12)) << target;
        EXPECT_NEAR(fin, target, 1e-9) << target;
    }
}

TEST(StepgenLoop, TrapezoidTakesAboutTheIdealTime)
{
    // 10 units at 20 u/s, 100 u/s^2: 0.2 s up, 0.3 s cruise, 0.2 s down = 0.7 s.
    stepgen_loop l{};
    double pos = 0.0;
    int i;
    for (i = 0; i < 2000 && std::fabs(pos - 10.0) > 1e-9; i++) {
        l.vel = stepgen_position_loop(&l, 10.0, pos, 20.0, 100.0, kT);
        pos += l.vel * kT;
    }
    EXPECT_GE(i, 700);
    EXPECT_LE(i, 720);
}

TEST(StepgenLoop, MovingCommandIsFollowedWithoutLag)
{
    stepgen_loop l{};
    double pos = 0.0, cmd = 0.0;
    for (int i = 0; i < 3000; i++) {
        cmd += 5.0 * kT;  // a 5 u/s ramp: within the limits after the first jump
        l.vel = stepgen_position_loop(&l, cmd, pos, 20.0, 100.0, kT);
        pos += l.vel * kT;
    }
    EXPECT_NEAR(l.vel, 5.0, 1e-6);
    EXPECT_NEAR(cmd - pos, 0.0, 0.01);
}

TEST(StepgenLoop, NoAccelLimitArrivesInOnePeriod)
{
    stepgen_loop l{};
    double v = stepgen_position_loop(&l, 0.005, 0.0, 20.0, 0.0, kT);
    EXPECT_DOUBLE_EQ(v, 5.0);
}

TEST(StepgenLoop, VelocityModeRampsAndLimits)
{
    stepgen_loop l{};
    l.vel = stepgen_velocity_loop(&l, 50.0, 20.0, 1000.0, kT);
    EXPECT_DOUBLE_EQ(l.vel, 1.0);
    for (int i = 0; i < 100; i++)
        l.vel = stepgen_velocity_loop(&l, 50.0, 20.0, 1000.0, kT);
    EXPECT_DOUBLE_EQ(l.vel, 20.0);
    EXPECT_DOUBLE_EQ(stepgen_velocity_loop(&l, -50.0, 20.0, 0.0, kT), -20.0);
}

TEST(StepgenLoop, StepRateLimitFollowsTheTiming)
{
    stepgen_timing t{1, 1, 1, 1, 1};
    EXPECT_DOUBLE_EQ(stepgen_max_freq(0, &t, 25000), 20000.0);
    EXPECT_DOUBLE_EQ(stepgen_max_freq(2, &t, 25000), 40000.0);
    EXPECT_DOUBLE_EQ(stepgen_max_freq(0, &t, 0), 0.0);
}

TEST(StepgenLoop, AddvalTruncatesTowardZeroAndClamps)
{
    EXPECT_EQ(stepgen_freq_to_addval(10000.0, 50000), STEPGEN_ONE_STEP / 2);
    EXPECT_EQ(stepgen_freq_to_addval(-10000.0, 50000), -STEPGEN_ONE_STEP / 2);
    EXPECT_EQ(stepgen_freq_to_addval(1e9, 50000), STEPGEN_ONE_STEP);
    EXPECT_LE(stepgen_addval_to_freq(stepgen_freq_to_addval(2000.0, 50000), 50000), 2000.0);
    EXPECT_DOUBLE_EQ(stepgen_accum_to_steps(STEPGEN_HALF_STEP + 3 * STEPGEN_ONE_STEP), 3.0);
}

}  // namespace
