// SPDX-License-Identifier: GPL-2.0-or-later
// motcmd's parser (user/motion/motcmd_parse.hpp): words -> command fields, and the
// one-line errors for bad words.
#include <gtest/gtest.h>

#include "motcmd_parse.hpp"

namespace {

using hal::motcmd_parse;

TEST(MotcmdParse, JogsAndAxes)
{
    auto r = motcmd_parse({"jog-incr", "1", "-2.5", "-10"});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cmd.command, MOTCMD_JOG_INCR);
    EXPECT_EQ(r->cmd.joint, 1);
    EXPECT_EQ(r->cmd.axis, 1);
    EXPECT_DOUBLE_EQ(r->cmd.offset, -2.5);
    EXPECT_DOUBLE_EQ(r->cmd.vel, 10);
    r = motcmd_parse({"jog-cont", "Z", "-3"});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cmd.axis, 2);
    EXPECT_EQ(r->cmd.joint, -1);
}

TEST(MotcmdParse, SpindleOnWaitAndCss)
{
    auto r = motcmd_parse({"spindle-on", "1000"});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cmd.command, MOTCMD_SPINDLE_ON);
    EXPECT_EQ(r->cmd.wait_for_at_speed, 0);
    r = motcmd_parse({"spindle-on", "-500", "0", "wait"});
    ASSERT_TRUE(r);
    EXPECT_DOUBLE_EQ(r->cmd.vel, -500);
    EXPECT_EQ(r->cmd.spindle, 0);
    EXPECT_EQ(r->cmd.wait_for_at_speed, 1);
    r = motcmd_parse({"spindle-on", "2000", "1", "10000", "3", "wait"});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cmd.spindle, 1);
    EXPECT_DOUBLE_EQ(r->cmd.css_factor, 10000);
    EXPECT_DOUBLE_EQ(r->cmd.xoffset, 3);
    EXPECT_EQ(r->cmd.wait_for_at_speed, 1);
    EXPECT_FALSE(motcmd_parse({"spindle-on", "2000", "1", "10000", "3", "later"}));
    EXPECT_FALSE(motcmd_parse({"spindle-on", "wait"}));
}

TEST(MotcmdParse, SynchronizedOutputsWithEndValues)
{
    auto r = motcmd_parse({"dout", "3", "1"});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cmd.now, 1);
    EXPECT_EQ(r->cmd.start, 1);
    EXPECT_EQ(r->cmd.end, 1);
    r = motcmd_parse({"dout", "3", "1", "sync", "0"});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cmd.now, 0);
    EXPECT_EQ(r->cmd.start, 1);
    EXPECT_EQ(r->cmd.end, 0);
    r = motcmd_parse({"aout", "1", "2.5", "sync", "-1"});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cmd.now, 0);
    EXPECT_DOUBLE_EQ(r->cmd.aout_start, 2.5);
    EXPECT_DOUBLE_EQ(r->cmd.aout_end, -1);
    r = motcmd_parse({"aout", "1", "2.5", "sync"});
    ASSERT_TRUE(r);
    EXPECT_DOUBLE_EQ(r->cmd.aout_end, 2.5);
    EXPECT_FALSE(motcmd_parse({"dout", "3", "1", "later"}));
    EXPECT_FALSE(motcmd_parse({"dout", "3", "1", "sync", "maybe"}));
}

TEST(MotcmdParse, MovesTakeUpToNineCoordinates)
{
    auto r = motcmd_parse({"line", "1", "2", "3", "10", "100"});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cmd.command, MOTCMD_SET_LINE);
    EXPECT_EQ(r->cmd.motion_type, MOTION_TYPE_FEED);
    EXPECT_DOUBLE_EQ(r->cmd.pos.v[2], 3);
    EXPECT_DOUBLE_EQ(r->cmd.vel, 10);
    EXPECT_DOUBLE_EQ(r->cmd.acc, 100);
    EXPECT_FALSE(motcmd_parse({"line", "1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12"}));
    r = motcmd_parse({"rapid", "0", "5", "5"});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cmd.motion_type, MOTION_TYPE_TRAVERSE);
}

TEST(MotcmdParse, Errors)
{
    auto r = motcmd_parse({"jog-cont", "0", "fast"});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "jog-cont: 'fast' is not a number");
    r = motcmd_parse({"jog-cont", "0"});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "jog-cont: usage: jog-cont JOINT|AXIS VEL");
    r = motcmd_parse({"fly"});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "unknown command 'fly' (motcmd --help lists them)");
    EXPECT_FALSE(motcmd_parse({"jog-cont", "0", "nan"}));
    EXPECT_FALSE(motcmd_parse({"term-cond", "round"}));
    EXPECT_FALSE(motcmd_parse({}));
}

TEST(MotcmdParse, CompFileLines)
{
    double n, f, r;
    ASSERT_TRUE(hal::motcmd_comp_line("10 9.99 10.03", 0, &n, &f, &r));
    EXPECT_DOUBLE_EQ(n, 10);
    EXPECT_NEAR(f, 0.01, 1e-12);
    EXPECT_NEAR(r, -0.03, 1e-12);
    ASSERT_TRUE(hal::motcmd_comp_line("  1 0.5 -0.5 ", 1, &n, &f, &r));
    EXPECT_DOUBLE_EQ(f, 0.5);
    EXPECT_FALSE(hal::motcmd_comp_line("# comment", 0, &n, &f, &r));
    EXPECT_FALSE(hal::motcmd_comp_line("1 2", 0, &n, &f, &r));
    EXPECT_FALSE(hal::motcmd_comp_line("1 2 3 4", 0, &n, &f, &r));
}

}  // namespace
