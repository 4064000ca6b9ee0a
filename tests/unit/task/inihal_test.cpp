// SPDX-License-Identifier: GPL-2.0-or-later
// The inihal pins without HAL (user/task/inihal_items.hpp): names and defaults from
// the INI, which commands a change sends; and [TRAJ]POSITION_FILE
// (user/task/position_file.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <unistd.h>

#include "inihal_items.hpp"
#include "position_file.hpp"
#include "task_config.hpp"

using namespace hal::task;

namespace {

const char* INI = R"(
[TRAJ]
COORDINATES = X Y Z
MAX_LINEAR_VELOCITY = 50
DEFAULT_LINEAR_VELOCITY = 10
MAX_LINEAR_ACCELERATION = 500
ARC_BLEND_OPTIMIZATION_DEPTH = 20
[KINS]
JOINTS = 3
[AXIS_X]
MAX_VELOCITY = 40
MAX_LIMIT = 100
[JOINT_0]
MAX_VELOCITY = 45
FERROR = 2
MIN_FERROR = 0.5
HOME = 3
HOME_SEQUENCE = 1
)";

TaskConfig config()
{
    auto ini = hal::ini::IniFile::parse(INI, "/cfg/m.ini");
    EXPECT_TRUE(ini);
    auto c = read_task_config(*ini);
    EXPECT_TRUE(c) << c.error().message;
    return *c;
}

struct Pins {
    TaskConfig cfg = config();
    std::vector<IniItem> items = inihal_items(cfg);
    std::vector<double> values;
    Pins()
    {
        for (const IniItem& it : items)
            values.push_back(it.get(cfg));
    }
    double& operator[](const std::string& name)
    {
        for (size_t i = 0; i < items.size(); ++i)
            if (items[i].name == name)
                return values[i];
        ADD_FAILURE() << "no pin " << name;
        static double none;
        return none;
    }
    std::vector<motion_command> apply() { return inihal_apply(items, values, cfg); }
};

}  // namespace

TEST(IniHal, EveryPinOfMotionMd16_1WithTheIniValue)
{
    Pins p;
    // 10 per joint, 4 per axis, 10 traj
    EXPECT_EQ(p.items.size(), 3u * 10 + 3 * 4 + 10);
    EXPECT_EQ(p["ini.0.max_velocity"], 45);
    EXPECT_EQ(p["ini.0.ferror"], 2);
    EXPECT_EQ(p["ini.0.min_ferror"], 0.5);
    EXPECT_EQ(p["ini.0.home"], 3);
    EXPECT_EQ(p["ini.0.home_sequence"], 1);
    EXPECT_EQ(p["ini.1.home_sequence"], 999);
    EXPECT_EQ(p["ini.x.max_velocity"], 40);
    EXPECT_EQ(p["ini.x.max_limit"], 100);
    EXPECT_EQ(p["ini.traj_max_velocity"], 50);
    EXPECT_EQ(p["ini.traj_default_velocity"], 10);
    EXPECT_EQ(p["ini.traj_max_acceleration"], 500);
    EXPECT_EQ(p["ini.traj_arc_blend_enable"], 1);
    EXPECT_EQ(p["ini.traj_arc_blend_fallback_enable"], 1);   // this planner's default (task.md)
    EXPECT_EQ(p["ini.traj_arc_blend_optimization_depth"], 20);
    EXPECT_EQ(p["ini.traj_arc_blend_gap_cycles"], 4);
    EXPECT_EQ(p["ini.traj_arc_blend_ramp_freq"], 100);
    EXPECT_DOUBLE_EQ(p["ini.traj_arc_blend_tangent_kink_ratio"], 0.1);
    for (const IniItem& it : p.items) {
        bool s32 = it.name.find("home_sequence") != std::string::npos ||
                   it.name.find("optimization_depth") != std::string::npos;
        EXPECT_EQ(it.type == IniPinType::S32, s32) << it.name;
    }
    EXPECT_TRUE(p.apply().empty()) << "nothing changed, nothing sent";
}

TEST(IniHal, AChangeSendsItsCommandOnce)
{
    Pins p;
    p["ini.0.ferror"] = 3;
    auto c = p.apply();
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].command, MOTCMD_SET_JOINT_MAX_FERROR);
    EXPECT_EQ(c[0].joint, 0);
    EXPECT_EQ(c[0].value, 3);
    EXPECT_EQ(p.cfg.joint[0].ferror, 3);
    EXPECT_TRUE(p.apply().empty()) << "sent once, not every cycle";

    p["ini.1.min_limit"] = -5;
    p["ini.1.max_limit"] = 5;
    c = p.apply();
    ASSERT_EQ(c.size(), 1u) << "both limits in one command";
    EXPECT_EQ(c[0].command, MOTCMD_SET_JOINT_POSITION_LIMITS);
    EXPECT_EQ(c[0].joint, 1);
    EXPECT_EQ(c[0].minLimit, -5);
    EXPECT_EQ(c[0].maxLimit, 5);

    p["ini.0.home"] = 7;
    p["ini.0.home_sequence"] = 2;
    c = p.apply();
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].command, MOTCMD_UPDATE_JOINT_HOMING_PARAMS);
    EXPECT_EQ(c[0].home, 7);
    EXPECT_EQ(c[0].home_sequence, 2);
    EXPECT_EQ(c[0].offset, 0);
}

TEST(IniHal, AxisAndTrajChanges)
{
    Pins p;
    p["ini.x.max_velocity"] = 20;
    p["ini.traj_max_velocity"] = 5;
    p["ini.traj_max_acceleration"] = 50;
    p["ini.traj_default_acceleration"] = 30;
    auto c = p.apply();
    std::map<int, motion_command> by;
    for (const motion_command& m : c)
        by[m.command] = m;
    EXPECT_EQ(c.size(), 4u);
    EXPECT_EQ(by[MOTCMD_SET_AXIS_VEL_LIMIT].axis, 0);
    EXPECT_EQ(by[MOTCMD_SET_AXIS_VEL_LIMIT].value, 20);
    EXPECT_EQ(by[MOTCMD_SET_VEL_LIMIT].vel, 5);
    EXPECT_EQ(by[MOTCMD_SET_VEL].ini_maxvel, 5);
    EXPECT_EQ(by[MOTCMD_SET_VEL].vel, 10);
    EXPECT_EQ(by[MOTCMD_SET_ACC].acc, 50);
    // task's own values follow too: the canon caps moves with them
    EXPECT_EQ(p.cfg.axis[0].max_vel, 20);
    EXPECT_EQ(p.cfg.max_vel, 5);
    EXPECT_EQ(p.cfg.default_acc, 30);

    p["ini.traj_arc_blend_enable"] = 0;
    p["ini.traj_arc_blend_tangent_kink_ratio"] = 0.2;
    c = p.apply();
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].command, MOTCMD_SETUP_ARC_BLENDS);
    EXPECT_EQ(c[0].mode, 0);
    EXPECT_EQ(c[0].count, 20);
    EXPECT_DOUBLE_EQ(c[0].tolerance, 0.2);
    EXPECT_EQ(c[0].scale, 100);
}

TEST(IniHal, NonFiniteValuesAreIgnored)
{
    Pins p;
    p["ini.0.max_velocity"] = std::nan("");
    EXPECT_TRUE(p.apply().empty());
    EXPECT_EQ(p.cfg.joint[0].max_vel, 45);
}

TEST(IniHal, StartupSendsArcBlendsAndMotorOffsets)
{
    TaskConfig c = config();
    c.motor_offset = {-1.5, 2};
    auto cmds = motion_init_commands(c);
    ASSERT_TRUE(cmds);
    int arc = 0;
    std::vector<std::pair<int, double>> offsets;
    int after_activate = 0;
    for (size_t i = 0; i < cmds->size(); ++i) {
        const motion_command& m = (*cmds)[i];
        if (m.command == MOTCMD_SETUP_ARC_BLENDS)
            ++arc;
        if (m.command == MOTCMD_SET_JOINT_MOTOR_OFFSET) {
            offsets.push_back({m.joint, m.offset});
            // motion.md 16.2: after the joint's JOINT_ACTIVATE
            if (i > 0 && (*cmds)[i - 1].command == MOTCMD_JOINT_ACTIVATE && (*cmds)[i - 1].joint == m.joint)
                ++after_activate;
        }
    }
    EXPECT_EQ(arc, 1);
    std::vector<std::pair<int, double>> want = {{0, -1.5}, {1, 2}};
    EXPECT_EQ(offsets, want);
    EXPECT_EQ(after_activate, 2);
}

TEST(PositionFile, RoundTripAndErrors)
{
    char dir[] = "/tmp/posfile.XXXXXX";
    ASSERT_NE(mkdtemp(dir), nullptr);
    std::string f = std::string(dir) + "/pos.txt";
    auto none = read_position_file(f);
    ASSERT_TRUE(none);
    EXPECT_TRUE(none->empty()) << "no file yet: nothing to restore";
    ASSERT_TRUE(write_position_file(f, {12.5, -3.25, 0.1}));
    std::ifstream in(f);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text, "12.50000000000000000\n-3.25000000000000000\n0.10000000000000001\n");
    EXPECT_NE(access((f + ".new").c_str(), F_OK), 0);
    auto back = read_position_file(f);
    ASSERT_TRUE(back);
    EXPECT_EQ(*back, (std::vector<double>{12.5, -3.25, 0.1}));
    EXPECT_EQ(motor_offsets_for(*back), (std::vector<double>{-12.5, 3.25, -0.1}));
    std::ofstream(f) << "1\n\n2x\n";
    auto bad = read_position_file(f);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().message, f + ":3: '2x' is not a joint position");
    EXPECT_FALSE(write_position_file(std::string(dir) + "/no/such/dir/p", {1}));
    std::remove(f.c_str());
    rmdir(dir);
}
