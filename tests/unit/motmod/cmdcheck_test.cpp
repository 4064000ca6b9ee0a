// SPDX-License-Identifier: GPL-2.0-or-later
// The command checks (kernel/motion/cmdcheck.h): what a hostile writer of the shared
// command slot can put there is refused before motion uses it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "cmdcheck.h"

namespace {

const cmdcheck_config cfg = {3, 1, 4, 2, false};

int check(const motion_command& c, const cmdcheck_config& k = cfg, std::string* why = nullptr)
{
    char msg[200];
    int r = cmdcheck(&c, &k, msg, sizeof(msg));
    if (why)
        *why = msg;
    return r;
}

motion_command cmd(int command)
{
    motion_command c{};
    c.command = command;
    return c;
}

TEST(CmdCheck, UnknownCommands)
{
    std::string why;
    for (int n : {0, -1, MOTCMD_LAST + 1, 1 << 30}) {
        EXPECT_EQ(check(cmd(n), cfg, &why), MOTION_CMD_UNKNOWN) << n;
        EXPECT_EQ(why, "unknown command " + std::to_string(n));
    }
    EXPECT_STREQ(cmdcheck_name(MOTCMD_JOG_CONT), "JOG_CONT");
    EXPECT_STREQ(cmdcheck_name(MOTCMD_SET_SPINDLE_PARAMS), "SET_SPINDLE_PARAMS");
    EXPECT_STREQ(cmdcheck_name(0), "?");
}

TEST(CmdCheck, NonFiniteAnywhereIsRefused)
{
    motion_command c = cmd(MOTCMD_ENABLE);
    EXPECT_EQ(check(c), MOTION_CMD_OK);
    c.spindle_params[4] = std::nan("");
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
    c = cmd(MOTCMD_ENABLE);
    c.pos.v[0] = INFINITY;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
}

TEST(CmdCheck, JointIndices)
{
    std::string why;
    motion_command c = cmd(MOTCMD_JOG_CONT);
    c.vel = 1;
    c.joint = 2;
    EXPECT_EQ(check(c), MOTION_CMD_OK);
    c.joint = 3;
    EXPECT_EQ(check(c, cfg, &why), MOTION_CMD_INVALID_PARAMS);
    EXPECT_EQ(why, "joint 3 out of range (0..2)");
    c.joint = -1;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
    c.joint = 0;
    c.vel = 0;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);  // a jog needs a velocity
    c = cmd(MOTCMD_JOINT_HOME);
    c.joint = -1;
    EXPECT_EQ(check(c), MOTION_CMD_OK);              // home all
    c.joint = -2;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
    c = cmd(MOTCMD_JOINT_UNHOME);
    c.joint = -2;
    EXPECT_EQ(check(c), MOTION_CMD_OK);              // volatile joints
    c.joint = -3;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
}

TEST(CmdCheck, TeleopJogsAddressAxes)
{
    cmdcheck_config teleop = cfg;
    teleop.teleop = true;
    motion_command c = cmd(MOTCMD_JOG_INCR);
    c.vel = 1;
    c.joint = 99;
    c.axis = 8;
    EXPECT_EQ(check(c, teleop), MOTION_CMD_OK);
    c.axis = 9;
    EXPECT_EQ(check(c, teleop), MOTION_CMD_INVALID_PARAMS);
}

TEST(CmdCheck, IoSpindleAndValueDomains)
{
    motion_command c = cmd(MOTCMD_SET_DOUT);
    c.out = 3;
    EXPECT_EQ(check(c), MOTION_CMD_OK);
    c.out = 4;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
    c = cmd(MOTCMD_SET_AOUT);
    c.out = 2;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
    c = cmd(MOTCMD_SPINDLE_ON);
    c.spindle = -1;
    EXPECT_EQ(check(c), MOTION_CMD_OK);  // all spindles
    c.spindle = 1;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
    c = cmd(MOTCMD_SET_SPINDLE_PARAMS);
    c.spindle = -1;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
    c.spindle = 0;
    c.spindle_params[1] = 100;
    EXPECT_EQ(check(c), MOTION_CMD_OK);
    c.spindle_params[0] = 200;  // min above max
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
    c = cmd(MOTCMD_SET_AXIS_EXT_OFFSET_LIMITS);
    c.axis = 2;
    EXPECT_EQ(check(c), MOTION_CMD_OK);  // 0, 0: no external offset on Z
    c.vel = -1;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
    c.vel = 1;
    c.axis = 9;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
    EXPECT_STREQ(cmdcheck_name(MOTCMD_SET_AXIS_EXT_OFFSET_LIMITS), "SET_AXIS_EXT_OFFSET_LIMITS");
    c = cmd(MOTCMD_SET_JOINT_VEL_LIMIT);
    c.joint = 0;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);  // 0 is no limit
    c.value = 5;
    EXPECT_EQ(check(c), MOTION_CMD_OK);
    c = cmd(MOTCMD_SET_JOINT_POSITION_LIMITS);
    c.minLimit = 1;
    c.maxLimit = -1;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
    c = cmd(MOTCMD_SET_TERM_COND);
    c.termCond = 3;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
    c = cmd(MOTCMD_SET_JOINT_HOMING_PARAMS);
    c.flags = 0x100;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
}

TEST(CmdCheck, MovesNeedPositiveVelocityAndAcceleration)
{
    motion_command c = cmd(MOTCMD_SET_LINE);
    c.vel = c.ini_maxvel = 10;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);  // acc 0
    c.acc = 100;
    EXPECT_EQ(check(c), MOTION_CMD_OK);
    c.command = MOTCMD_SET_CIRCLE;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);  // zero normal
    c.normal[2] = 1;
    EXPECT_EQ(check(c), MOTION_CMD_OK);
    c.command = MOTCMD_PROBE;
    c.probe_type = 4;
    EXPECT_EQ(check(c), MOTION_CMD_INVALID_PARAMS);
}

// garbage in every byte: always one of the known answers, never a crash (ASan/UBSan
// builds run this too)
TEST(CmdCheck, RandomGarbage)
{
    std::mt19937_64 rng(14);
    for (int i = 0; i < 200000; ++i) {
        motion_command c;
        unsigned char* p = reinterpret_cast<unsigned char*>(&c);
        for (size_t b = 0; b < sizeof(c); ++b)
            p[b] = static_cast<unsigned char>(rng());
        if (i & 1)
            c.command = static_cast<int>(rng() % (MOTCMD_LAST + 2));
        int r = check(c);
        ASSERT_TRUE(r == MOTION_CMD_OK || r == MOTION_CMD_UNKNOWN || r == MOTION_CMD_INVALID_PARAMS);
    }
}

}  // namespace
