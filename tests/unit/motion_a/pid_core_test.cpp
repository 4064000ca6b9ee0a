// SPDX-License-Identifier: GPL-2.0-or-later
// pid(9) loop math (kernel/components/pid_core.h): each gain and limit as the
// page defines it, the integrator's windup rules, enable, and the -deriv inputs.
#include <gtest/gtest.h>

#include "pid_core.h"

namespace {

constexpr long kPeriodNs = 1000000;  // 1 ms: derivatives are 1000 * the change
constexpr double kPeriodS = 1e-3;

struct Loop {
    pid_state st{};
    pid_gains g{};
    pid_in in{};
    pid_out o{};

    Loop()
    {
        g.Pgain = 1.0;
        in.enable = true;
    }
    // One period with the given command and feedback.
    const pid_out& step(double command, double feedback)
    {
        in.command = command;
        in.feedback = feedback;
        pid_step(&st, &g, &in, kPeriodNs, &o);
        return o;
    }
};

TEST(Pid, OutputIsPgainTimesError)
{
    Loop l;
    l.g.Pgain = 2.0;
    l.step(1.0, 0.25);
    EXPECT_DOUBLE_EQ(l.o.error, 0.75);
    EXPECT_DOUBLE_EQ(l.o.output, 1.5);
}

TEST(Pid, ErrorPreviousTargetComparesFeedbackWithTheLastCommand)
{
    Loop l;
    l.in.error_previous_target = true;
    l.step(0.0, 0.0);
    l.step(1.0, 0.0);  // the target is still the previous command, 0
    EXPECT_DOUBLE_EQ(l.o.error, 0.0);
    l.step(1.0, 0.0);
    EXPECT_DOUBLE_EQ(l.o.error, 1.0);
}

TEST(Pid, FirstPeriodHasNoDerivativeSpike)
{
    Loop l;
    l.g.FF1 = 1.0;
    l.g.Dgain = 1.0;
    l.in.error_previous_target = true;
    l.step(5.0, 4.0);
    EXPECT_DOUBLE_EQ(l.o.commandD, 0.0);
    EXPECT_DOUBLE_EQ(l.o.errorD, 0.0);
    EXPECT_DOUBLE_EQ(l.o.output, 1.0);  // target is the command itself on the first period
}

TEST(Pid, BiasIsAddedToTheOutput)
{
    Loop l;
    l.g.bias = 0.5;
    l.step(1.0, 0.0);
    EXPECT_DOUBLE_EQ(l.o.output, 1.5);
}

TEST(Pid, IgainMultipliesTheIntegralOfError)
{
    Loop l;
    l.g.Pgain = 0.0;
    l.g.Igain = 20.0;
    for (int i = 0; i < 10; i++)
        l.step(0.02, 0.0);
    EXPECT_NEAR(l.o.errorI, 0.02 * 10 * kPeriodS, 1e-15);
    EXPECT_NEAR(l.o.output, 20.0 * 0.0002, 1e-12);
}

TEST(Pid, MaxerrorILimitsTheIntegrator)
{
    Loop l;
    l.g.Igain = 1.0;
    l.g.maxerrorI = 0.0025;
    for (int i = 0; i < 10; i++)
        l.step(1.0, 0.0);
    EXPECT_DOUBLE_EQ(l.o.errorI, 0.0025);
    for (int i = 0; i < 10; i++)
        l.step(-1.0, 0.0);
    EXPECT_DOUBLE_EQ(l.o.errorI, -0.0025);
}

TEST(Pid, DgainMultipliesTheErrorDerivative)
{
    Loop l;
    l.g.Pgain = 0.0;
    l.g.Dgain = 5.0;
    l.step(0.02, 0.0);
    l.step(0.03, 0.0);
    EXPECT_NEAR(l.o.errorD, 0.01 / kPeriodS, 1e-9);
    EXPECT_NEAR(l.o.output, 5.0 * 10.0, 1e-9);
}

TEST(Pid, MaxerrorDLimitsTheErrorDerivative)
{
    Loop l;
    l.g.Pgain = 0.0;
    l.g.Dgain = 1.0;
    l.g.maxerrorD = 3.0;
    l.step(0.0, 0.0);
    l.step(1.0, 0.0);
    EXPECT_DOUBLE_EQ(l.o.errorD, 3.0);
    l.step(0.0, 0.0);
    EXPECT_DOUBLE_EQ(l.o.errorD, -3.0);
}

TEST(Pid, DeadbandIsSubtractedOutsideAndZeroInside)
{
    Loop l;
    l.g.deadband = 0.1;
    l.step(0.3, 0.0);
    EXPECT_NEAR(l.o.output, 0.2, 1e-15);
    EXPECT_DOUBLE_EQ(l.o.error, 0.3);  // the error pin is not affected
    l.step(-0.3, 0.0);
    EXPECT_NEAR(l.o.output, -0.2, 1e-15);
    l.step(0.05, 0.0);
    EXPECT_DOUBLE_EQ(l.o.output, 0.0);
    l.step(-0.1, 0.0);
    EXPECT_DOUBLE_EQ(l.o.output, 0.0);
}

TEST(Pid, MaxerrorLimitsTheErrorUsedByTheTerms)
{
    Loop l;
    l.g.Pgain = 2.0;
    l.g.maxerror = 1.0;
    l.step(5.0, 0.0);
    EXPECT_DOUBLE_EQ(l.o.error, 5.0);
    EXPECT_DOUBLE_EQ(l.o.output, 2.0);
    l.step(-5.0, 0.0);
    EXPECT_DOUBLE_EQ(l.o.output, -2.0);
}

TEST(Pid, FF0IsProportionalToTheCommand)
{
    Loop l;
    l.g.Pgain = 0.0;
    l.g.FF0 = 3.0;
    l.step(2.0, 2.0);
    EXPECT_DOUBLE_EQ(l.o.output, 6.0);
}

TEST(Pid, FF1FF2FF3UseTheCommandDerivatives)
{
    Loop l;
    l.g.Pgain = 0.0;
    l.step(0.0, 0.0);
    l.step(0.001, 0.0);  // commandD 1, commandDD 1000, commandDDD 1e6
    EXPECT_NEAR(l.o.commandD, 1.0, 1e-12);
    EXPECT_NEAR(l.o.commandDD, 1000.0, 1e-9);
    EXPECT_NEAR(l.o.commandDDD, 1e6, 1e-6);
    l.g.FF1 = 2.0;
    l.step(0.002, 0.0);  // commandD 1, commandDD 0, commandDDD -1e6
    EXPECT_NEAR(l.o.output, 2.0, 1e-9);
    l.g.FF1 = 0.0;
    l.g.FF2 = 0.5;
    l.step(0.004, 0.0);  // commandD 2, commandDD 1000
    EXPECT_NEAR(l.o.output, 500.0, 1e-6);
    l.g.FF2 = 0.0;
    l.g.FF3 = 1e-6;
    l.step(0.006, 0.0);  // commandD 2, commandDD 0, commandDDD -1e6
    EXPECT_NEAR(l.o.output, -1.0, 1e-6);
}

TEST(Pid, MaxcmdLimitsEachCommandDerivative)
{
    Loop l;
    l.g.maxcmdD = 0.5;
    l.g.maxcmdDD = 100.0;
    l.g.maxcmdDDD = 1000.0;
    l.step(0.0, 0.0);
    l.step(1.0, 1.0);
    EXPECT_DOUBLE_EQ(l.o.commandD, 0.5);
    EXPECT_DOUBLE_EQ(l.o.commandDD, 100.0);
    EXPECT_DOUBLE_EQ(l.o.commandDDD, 1000.0);
    l.step(0.0, 0.0);
    EXPECT_DOUBLE_EQ(l.o.commandD, -0.5);
    EXPECT_DOUBLE_EQ(l.o.commandDD, -100.0);
    EXPECT_DOUBLE_EQ(l.o.commandDDD, -1000.0);
}

TEST(Pid, MaxoutputSaturatesAndCountsThePeriods)
{
    Loop l;
    l.g.Pgain = 10.0;
    l.g.maxoutput = 2.0;
    for (int i = 0; i < 3; i++)
        l.step(1.0, 0.0);
    EXPECT_DOUBLE_EQ(l.o.output, 2.0);
    EXPECT_TRUE(l.o.saturated);
    EXPECT_EQ(l.o.saturated_count, 3);
    EXPECT_NEAR(l.o.saturated_s, 3 * kPeriodS, 1e-15);
    l.step(-1.0, 0.0);
    EXPECT_DOUBLE_EQ(l.o.output, -2.0);
    EXPECT_EQ(l.o.saturated_count, 4);
    l.step(0.1, 0.0);
    EXPECT_DOUBLE_EQ(l.o.output, 1.0);
    EXPECT_FALSE(l.o.saturated);
    EXPECT_EQ(l.o.saturated_count, 0);
    EXPECT_DOUBLE_EQ(l.o.saturated_s, 0.0);
}

TEST(Pid, IntegratorHoldsWhileTheOutputIsSaturated)
{
    Loop l;
    l.g.Pgain = 0.0;
    l.g.Igain = 1000.0;
    l.g.maxoutput = 2.5;
    l.step(1.0, 0.0);  // errorI 0.001 -> output 1
    l.step(1.0, 0.0);  // 0.002 -> 2
    EXPECT_DOUBLE_EQ(l.o.errorI, 0.002);
    l.step(1.0, 0.0);  // 0.003 would give 3: limited, errorI holds
    EXPECT_TRUE(l.o.saturated);
    EXPECT_DOUBLE_EQ(l.o.errorI, 0.002);
    l.step(1.0, 0.0);
    EXPECT_DOUBLE_EQ(l.o.errorI, 0.002);
    l.step(-1.0, 0.0);  // unwinds at once when the error reverses
    EXPECT_DOUBLE_EQ(l.o.errorI, 0.001);
    EXPECT_FALSE(l.o.saturated);
}

TEST(Pid, DisableZeroesTheOutputAndResetsTheIntegrator)
{
    Loop l;
    l.g.Igain = 1.0;
    l.g.bias = 1.0;
    l.step(1.0, 0.0);
    l.step(1.0, 0.0);
    ASSERT_GT(l.o.errorI, 0.0);
    l.in.enable = false;
    l.step(1.0, 0.0);
    EXPECT_DOUBLE_EQ(l.o.output, 0.0);  // bias too
    EXPECT_DOUBLE_EQ(l.o.errorI, 0.0);
    EXPECT_DOUBLE_EQ(l.o.error, 1.0);
    l.in.enable = true;
    l.step(1.0, 0.0);  // starts integrating from 0, no derivative spike
    EXPECT_DOUBLE_EQ(l.o.errorI, 0.001);
    EXPECT_DOUBLE_EQ(l.o.errorD, 0.0);
}

TEST(Pid, DerivPinsReplaceTheNumericEstimates)
{
    Loop l;
    l.g.Pgain = 0.0;
    l.g.Dgain = 1.0;
    l.g.FF1 = 10.0;
    l.in.has_command_deriv = true;
    l.in.command_deriv = 3.0;
    l.in.has_feedback_deriv = true;
    l.in.feedback_deriv = 1.0;
    l.step(0.0, 0.0);
    l.step(7.0, 2.0);  // the numeric derivatives would be huge
    EXPECT_DOUBLE_EQ(l.o.commandD, 3.0);
    EXPECT_DOUBLE_EQ(l.o.errorD, 2.0);
    EXPECT_DOUBLE_EQ(l.o.output, 2.0 + 30.0);
}

TEST(Pid, OneDerivPinAffectsTheDTermToo)
{
    Loop l;
    l.g.Pgain = 0.0;
    l.g.Dgain = 1.0;
    l.in.has_feedback_deriv = true;
    l.in.feedback_deriv = 4.0;
    l.step(0.0, 0.0);
    l.step(0.001, 0.0);  // commandD estimated: 1
    EXPECT_NEAR(l.o.errorD, 1.0 - 4.0, 1e-12);
}

TEST(Pid, IndexEnableFallingEdgeKeepsTheCommandDerivative)
{
    Loop l;
    l.g.Pgain = 0.0;
    l.g.FF1 = 1.0;
    l.in.index_enable = true;
    l.step(0.0, 0.0);
    l.step(0.001, 0.0);
    EXPECT_NEAR(l.o.output, 1.0, 1e-12);
    l.in.index_enable = false;  // the encoder reset: the command jumps back
    l.step(-5.0, -5.0);
    EXPECT_NEAR(l.o.commandD, 1.0, 1e-12);
    EXPECT_NEAR(l.o.output, 1.0, 1e-12);
    l.step(-4.999, -4.999);  // the next period differentiates normally again
    EXPECT_NEAR(l.o.commandD, 1.0, 1e-9);
}

TEST(Pid, ZeroLimitsMeanNoLimit)
{
    EXPECT_DOUBLE_EQ(pid_limit(1e9, 0.0), 1e9);
    EXPECT_DOUBLE_EQ(pid_limit(-1e9, 0.0), -1e9);
    EXPECT_DOUBLE_EQ(pid_limit(5.0, 2.0), 2.0);
    EXPECT_DOUBLE_EQ(pid_deadband(0.5, 0.0), 0.5);
}

}  // namespace
