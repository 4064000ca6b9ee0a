// SPDX-License-Identifier: GPL-2.0-or-later
// at_pid(9) relay auto tune (kernel/components/at_pid_core.h) against a simulated
// plant e^(-L s)/s: an integrator behind a dead time L. Under a relay of +-d its
// error is a triangle wave of period 4 L and amplitude d L, so the tune must find
// ultimate-period 4 L and ultimate-gain 4 d / (pi d L) = 4 / (pi L).
#include <gtest/gtest.h>

#include <cmath>
#include <deque>

#include "at_pid_core.h"

namespace {

constexpr long kPeriodNs = 1000000;
constexpr double kDt = 1e-3;
constexpr int kDelayPeriods = 50;
// The tuner acts on the plant output of the previous period: one more period of dead time.
constexpr double kL = (kDelayPeriods + 1) * kDt;

struct Plant {  // dead time, then an integrator
    std::deque<double> line = std::deque<double>(kDelayPeriods, 0.0);
    double y = 0.0;
    double step(double u)
    {
        line.push_back(u);
        y += line.front() * kDt;
        line.pop_front();
        return y;
    }
};

struct Tuner {
    at_pid_tune t{};
    at_pid_tune_cfg c{};
    pid_gains g{};
    Plant plant;
    double out = 0.0;

    Tuner()
    {
        c.tune_mode = true;
        c.tune_start = true;
        c.tune_cycles = 20;
        c.tune_effort = 1.0;
        g.Pgain = 1.0;
    }
    at_pid_tune_result step(bool enable = true, double command = 0.0)
    {
        at_pid_tune_result r = at_pid_tune_step(&t, &c, enable, command - plant.y, kPeriodNs, &g, &out);
        plant.step(out);
        return r;
    }
    // Runs until the tune finishes; returns the number of periods, or -1.
    int run(int max_periods)
    {
        for (int i = 0; i < max_periods; i++)
            if (step() == AT_PID_DONE)
                return i + 1;
        return -1;
    }
};

TEST(AtPidTune, IdleUnlessEnableTuneModeAndTuneStart)
{
    Tuner tu;
    tu.c.tune_start = false;
    EXPECT_EQ(tu.step(), AT_PID_NOT_TUNING);
    tu.c.tune_start = true;
    tu.c.tune_mode = false;
    EXPECT_EQ(tu.step(), AT_PID_NOT_TUNING);
    tu.c.tune_mode = true;
    EXPECT_EQ(tu.step(false), AT_PID_NOT_TUNING);
    EXPECT_EQ(tu.step(true), AT_PID_RELAY);
}

TEST(AtPidTune, RelayDrivesTowardTheCommand)
{
    Tuner tu;
    tu.g.bias = 0.25;
    tu.step(true, 1.0);
    EXPECT_DOUBLE_EQ(tu.out, 1.25);
    tu.plant.y = 2.0;
    tu.step(true, 1.0);
    EXPECT_DOUBLE_EQ(tu.out, -0.75);
}

TEST(AtPidTune, RelayOutputIsLimitedByMaxoutput)
{
    Tuner tu;
    tu.c.tune_effort = 5.0;
    tu.g.maxoutput = 2.0;
    tu.step(true, 1.0);
    EXPECT_DOUBLE_EQ(tu.out, 2.0);
}

TEST(AtPidTune, FindsTheUltimateGainAndPeriodOfThePlant)
{
    Tuner tu;
    ASSERT_GT(tu.run(100000), 0);
    EXPECT_NEAR(tu.t.ultimate_period, 4 * kL, 2 * kDt);
    EXPECT_NEAR(tu.t.ultimate_gain, 4 / (M_PI * kL), 0.03 * 4 / (M_PI * kL));
}

TEST(AtPidTune, ZieglerNicholsPidGains)
{
    Tuner tu;
    tu.g.FF1 = 7.0;
    ASSERT_GT(tu.run(100000), 0);
    double ku = tu.t.ultimate_gain, pu = tu.t.ultimate_period;
    EXPECT_DOUBLE_EQ(tu.g.Pgain, 0.6 * ku);
    EXPECT_DOUBLE_EQ(tu.g.Igain, 1.2 * ku / pu);
    EXPECT_DOUBLE_EQ(tu.g.Dgain, 0.075 * ku * pu);
    EXPECT_DOUBLE_EQ(tu.g.FF1, 0.0);
}

TEST(AtPidTune, TuneType1GivesPiAndFF1)
{
    Tuner tu;
    tu.c.tune_type = 1;
    tu.g.Dgain = 3.0;
    ASSERT_GT(tu.run(100000), 0);
    double ku = tu.t.ultimate_gain, pu = tu.t.ultimate_period;
    EXPECT_DOUBLE_EQ(tu.g.Pgain, 0.45 * ku);
    EXPECT_DOUBLE_EQ(tu.g.Igain, 0.54 * ku / pu);
    EXPECT_DOUBLE_EQ(tu.g.Dgain, 0.0);
    EXPECT_DOUBLE_EQ(tu.g.FF1, 1.0);
}

TEST(AtPidTune, MoreCyclesTakeLonger)
{
    Tuner few, many;
    few.c.tune_cycles = 4;
    many.c.tune_cycles = 40;
    int n_few = few.run(100000), n_many = many.run(100000);
    ASSERT_GT(n_few, 0);
    EXPECT_GT(n_many, n_few * 5);
}

TEST(AtPidTune, DisableOrTuneModeAborts)
{
    Tuner tu;
    EXPECT_EQ(tu.step(), AT_PID_RELAY);
    EXPECT_EQ(tu.step(false), AT_PID_ABORTED);
    EXPECT_EQ(tu.step(false), AT_PID_NOT_TUNING);
    EXPECT_EQ(tu.step(true), AT_PID_RELAY);
    tu.c.tune_mode = false;
    EXPECT_EQ(tu.step(), AT_PID_ABORTED);
    EXPECT_DOUBLE_EQ(tu.g.Pgain, 1.0);  // gains untouched
}

}  // namespace
