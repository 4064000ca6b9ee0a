// SPDX-License-Identifier: GPL-2.0-or-later
// The free-mode planner (kernel/motion/freetp.h): exact velocity/acceleration limits,
// exact arrival, stop on disable, period as an input.
#include <gtest/gtest.h>

#include <cmath>

#include "freetp.h"

namespace {

struct Trace {
    double max_vel = 0, max_acc = 0;
    int steps = 0;
};

// run until inactive (or max_steps); velocity and acceleration from the positions
Trace run(freetp& tp, double dt, int max_steps = 1000000)
{
    Trace t;
    double prev_pos = tp.curr_pos, prev_vel = tp.curr_vel;
    for (; t.steps < max_steps; ++t.steps) {
        freetp_update(&tp, dt);
        double v = (tp.curr_pos - prev_pos) / dt;
        t.max_vel = std::max(t.max_vel, std::fabs(v));
        t.max_acc = std::max(t.max_acc, std::fabs(v - prev_vel) / dt);
        prev_pos = tp.curr_pos;
        prev_vel = v;
        if (!tp.active)
            break;
    }
    return t;
}

freetp make(double pos, double vmax, double amax)
{
    freetp tp{};
    freetp_reset(&tp, pos);
    tp.max_vel = vmax;
    tp.max_acc = amax;
    tp.enable = true;
    return tp;
}

TEST(FreeTp, LongMoveReachesLimitsExactlyAndLandsOnTarget)
{
    for (double dt : {0.001, 0.0005, 0.002}) {
        freetp tp = make(0.0, 10.0, 100.0);
        tp.pos_cmd = 5.0;
        Trace t = run(tp, dt);
        EXPECT_NEAR(t.max_vel, 10.0, 1e-9) << dt;
        EXPECT_LE(t.max_vel, 10.0 + 1e-9);
        EXPECT_LE(t.max_acc, 100.0 * (1 + 1e-6));
        EXPECT_NEAR(t.max_acc, 100.0, 1e-3);
        EXPECT_EQ(tp.curr_pos, 5.0);
        EXPECT_EQ(tp.curr_vel, 0.0);
        // about 0.1 s accelerating/decelerating + 0.4 s cruising
        EXPECT_NEAR(t.steps * dt, 0.6, 0.01);
    }
}

TEST(FreeTp, ShortMoveIsATriangleBelowMaxVel)
{
    freetp tp = make(1.0, 10.0, 100.0);
    tp.pos_cmd = 0.9;  // 0.1: peak sqrt(a d) ~ 3.16
    Trace t = run(tp, 0.001);
    EXPECT_LT(t.max_vel, 3.2);
    EXPECT_LE(t.max_acc, 100.0 * (1 + 1e-6));
    EXPECT_EQ(tp.curr_pos, 0.9);
}

TEST(FreeTp, DisableDeceleratesAtMaxAccAndKeepsThePosition)
{
    freetp tp = make(0.0, 10.0, 100.0);
    tp.pos_cmd = 100.0;
    for (int i = 0; i < 300; ++i)
        freetp_update(&tp, 0.001);
    ASSERT_DOUBLE_EQ(tp.curr_vel, 10.0);
    tp.enable = false;
    Trace t = run(tp, 0.001);
    EXPECT_LE(t.max_acc, 100.0 * (1 + 1e-6));
    EXPECT_EQ(tp.curr_vel, 0.0);
    EXPECT_EQ(tp.pos_cmd, tp.curr_pos);
    EXPECT_NEAR(t.steps, 100, 2);  // 10 / 100 = 0.1 s
}

TEST(FreeTp, LoweringMaxVelDeceleratesInsteadOfJumping)
{
    freetp tp = make(0.0, 10.0, 100.0);
    tp.pos_cmd = 100.0;
    for (int i = 0; i < 300; ++i)
        freetp_update(&tp, 0.001);
    tp.max_vel = 2.0;
    double prev = tp.curr_vel;
    for (int i = 0; i < 200; ++i) {
        freetp_update(&tp, 0.001);
        EXPECT_LE(std::fabs(tp.curr_vel - prev), 0.1 + 1e-12);
        prev = tp.curr_vel;
    }
    EXPECT_DOUBLE_EQ(tp.curr_vel, 2.0);
}

TEST(FreeTp, NegativeDirectionAndReversal)
{
    freetp tp = make(0.0, 5.0, 50.0);
    tp.pos_cmd = 3.0;
    for (int i = 0; i < 100; ++i)
        freetp_update(&tp, 0.001);
    tp.pos_cmd = -2.0;  // reverse while moving forward
    Trace t = run(tp, 0.001);
    EXPECT_LE(t.max_vel, 5.0 + 1e-9);
    EXPECT_LE(t.max_acc, 50.0 * (1 + 1e-6));
    EXPECT_EQ(tp.curr_pos, -2.0);
}

TEST(FreeTp, BadLimitsDoNotMove)
{
    freetp tp = make(1.0, 0.0, 100.0);
    tp.pos_cmd = 2.0;
    freetp_update(&tp, 0.001);
    EXPECT_EQ(tp.curr_pos, 1.0);
    EXPECT_FALSE(tp.active);
    tp.max_vel = 1.0;
    tp.max_acc = -1.0;
    freetp_update(&tp, 0.001);
    EXPECT_EQ(tp.curr_pos, 1.0);
}

}  // namespace
