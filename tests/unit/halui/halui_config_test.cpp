// INI keys halui reads (user/halui/halui_config.cpp) and task's status -> StatusView.
#include <gtest/gtest.h>

#include <cmath>

#include "halui_config.hpp"
#include "halui_status.hpp"

using namespace hal;
using namespace hal::halui;

static Result<Config> config(const std::string& text)
{
    auto ini = ini::IniFile::parse(text, "/cfg/m.ini");
    EXPECT_TRUE(ini) << (ini ? "" : ini.error().message);
    return read_config(*ini);
}

TEST(HaluiConfig, Defaults)
{
    auto c = config("[EMC]\nVERSION = 1\n");
    ASSERT_TRUE(c);
    EXPECT_EQ(c->joints, 3);
    EXPECT_EQ(c->axes, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(c->spindles, 1);
    EXPECT_EQ(c->max_feed_override, 1.0);
    EXPECT_EQ(c->min_spindle_override, 0.0);
    EXPECT_EQ(c->max_spindle_override, 1.0);
    EXPECT_EQ(c->max_velocity, 1.0);
    EXPECT_TRUE(c->mdi.empty());
}

TEST(HaluiConfig, MachineShapeClampsAndMdi)
{
    auto c = config("[TRAJ]\nCOORDINATES = X Y Y Z A\nSPINDLES = 2\nMAX_LINEAR_VELOCITY = 80\n"
                    "[AXIS_X]\nMAX_VELOCITY = 10\n[DISPLAY]\nMAX_FEED_OVERRIDE = 1.5\n"
                    "MIN_SPINDLE_OVERRIDE = 0.5\nMAX_SPINDLE_OVERRIDE = 1.2\n"
                    "[HALUI]\nMDI_COMMAND = G0 X0\nMDI_COMMAND = G1 X1 F100\n");
    ASSERT_TRUE(c) << c.error().message;
    EXPECT_EQ(c->joints, 5);   // a gantry: one joint per letter
    EXPECT_EQ(c->axes, (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(c->spindles, 2);
    EXPECT_EQ(c->max_velocity, 80);
    EXPECT_EQ(c->max_feed_override, 1.5);
    EXPECT_EQ(c->min_spindle_override, 0.5);
    EXPECT_EQ(c->max_spindle_override, 1.2);
    EXPECT_EQ(c->mdi, (std::vector<std::string>{"G0 X0", "G1 X1 F100"}));
    auto k = config("[KINS]\nJOINTS = 4\n[AXIS_X]\nMAX_VELOCITY = 12\n");
    ASSERT_TRUE(k);
    EXPECT_EQ(k->joints, 4);
    EXPECT_EQ(k->max_velocity, 12);   // no [TRAJ]MAX_LINEAR_VELOCITY
}

TEST(HaluiConfig, BadValuesNameFileAndLine)
{
    std::string many = "[HALUI]\n";
    for (int k = 0; k < 65; ++k)
        many += "MDI_COMMAND = G0 X" + std::to_string(k) + "\n";
    auto c = config(many);
    ASSERT_FALSE(c);
    EXPECT_EQ(c.error().message, "/cfg/m.ini:66: [HALUI]MDI_COMMAND: more than 64 commands");
    many.resize(many.rfind("MDI_COMMAND"));
    EXPECT_TRUE(config(many));   // 64 are fine

    c = config("[DISPLAY]\n\nMAX_FEED_OVERRIDE = fast\n");
    ASSERT_FALSE(c);
    EXPECT_EQ(c.error().message.rfind("/cfg/m.ini:3: [DISPLAY]MAX_FEED_OVERRIDE: 'fast'", 0), 0u)
        << c.error().message;
    c = config("[DISPLAY]\nMIN_SPINDLE_OVERRIDE = 2\nMAX_SPINDLE_OVERRIDE = 1\n");
    ASSERT_FALSE(c);
    EXPECT_EQ(c.error().message, "/cfg/m.ini:3: [DISPLAY]MAX_SPINDLE_OVERRIDE: 1 is below MIN_SPINDLE_OVERRIDE 2");
    c = config("[DISPLAY]\nMAX_FEED_OVERRIDE = -1\n");
    ASSERT_FALSE(c);
    EXPECT_EQ(c.error().message, "/cfg/m.ini:2: [DISPLAY]MAX_FEED_OVERRIDE: -1 out of range 0..1e+06");
    c = config("[TRAJ]\nCOORDINATES = X Q\n");
    ASSERT_FALSE(c);
    EXPECT_EQ(c.error().message, "/cfg/m.ini:2: [TRAJ]COORDINATES: 'Q' is not one of X Y Z A B C U V W");
    c = config("[KINS]\nJOINTS = 17\n");
    ASSERT_FALSE(c);
    EXPECT_EQ(c.error().message, "/cfg/m.ini:2: [KINS]JOINTS: 17 out of range 1..16");
    c = config("[HALUI]\nMDI_COMMAND = G0 X0\nMDI_COMMAND =\n");
    ASSERT_FALSE(c);
    EXPECT_EQ(c.error().message, "/cfg/m.ini:3: [HALUI]MDI_COMMAND: empty command");
    c = config("[TRAJ]\nMAX_LINEAR_VELOCITY = 1x\n");
    ASSERT_FALSE(c);
    EXPECT_EQ(c.error().message.rfind("/cfg/m.ini:2: [TRAJ]MAX_LINEAR_VELOCITY", 0), 0u);
}

TEST(HaluiStatus, ParsesTheKeysHaluiShows)
{
    std::map<std::string, std::string> st = {
        {"task.state", "ON"},
        {"task.mode", "MDI"},
        {"task.interp", "WAITING"},
        {"traj.mode", "COORD"},
        {"traj.axes", "XYZ"},
        {"traj.position", "1.000000 2.000000 3.000000"},
        {"traj.actual_position", "1.500000 2.500000 3.500000"},
        {"task.g5x_offset", "1.000000 0.000000 0.000000"},
        {"task.g92_offset", "0.000000 0.500000 0.000000"},
        {"task.tool_offset", "0.000000 0.000000 3.000000"},
        {"joint.1.homed", "1"},
        {"joint.1.max_hard_limit", "1"},
        {"spindle.0.direction", "-1"},
        {"spindle.0.enabled", "1"},
        {"spindle.0.override", "0.800000"},
        {"io.tool_in_spindle", "2"},
        {"tool.count", "2"},
        {"tool.0", "T1 P1 Z+10.000000 D+6.000000 ;one"},
        {"tool.1", "T2 P2 Z+20.000000 D+4.500000 ;two D9"},
        {"traj.feed_scale", "garbage"},
    };
    StatusView s = parse_status(st, 3, 1);
    EXPECT_EQ(s.state, "ON");
    EXPECT_EQ(s.interp, "WAITING");
    EXPECT_EQ(s.pos_cmd[2], 3.0);
    EXPECT_EQ(s.pos_fb[0], 1.5);
    EXPECT_TRUE(s.joints[1].homed);
    EXPECT_TRUE(s.joints[1].max_hard);
    EXPECT_FALSE(s.joints[0].homed);
    EXPECT_EQ(s.spindles[0].direction, -1);
    EXPECT_EQ(s.spindles[0].scale, 0.8);
    EXPECT_EQ(s.tool, 2);
    EXPECT_EQ(s.tool_diameter, 4.5);
    EXPECT_EQ(s.feed_scale, 0.0);
    EXPECT_DOUBLE_EQ(relative_position(s, 0), 0.5);    // 1.5 - G5x 1
    EXPECT_DOUBLE_EQ(relative_position(s, 1), 2.0);    // 2.5 - G92 0.5
    EXPECT_DOUBLE_EQ(relative_position(s, 2), 0.5);    // 3.5 - tool 3
    s.rotation_xy = 90;   // the work frame turned by 90 degrees: X reads machine Y
    EXPECT_NEAR(relative_position(s, 0), 2.5, 1e-9);
    EXPECT_NEAR(relative_position(s, 1), -0.5 - 0.5, 1e-9);
}

TEST(HaluiStatus, NoToolNoDiameter)
{
    StatusView s = parse_status({{"io.tool_in_spindle", "0"}, {"tool.count", "1"}, {"tool.0", "T0 P0 D+1.0"}}, 1, 0);
    EXPECT_EQ(s.tool_diameter, 0.0);
    EXPECT_TRUE(s.spindles.empty());
}
