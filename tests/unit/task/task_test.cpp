// SPDX-License-Identifier: GPL-2.0-or-later
// task_test.cpp - task without a machine: the state/mode/command rules, INI ->
// configuration -> motion start-up commands, and the canon -> work queue translation
// (driven directly and through the interpreter).
#include <gtest/gtest.h>

#include <cmath>

#include "rs274/interp.hpp"
#include "task_canon.hpp"
#include "task_config.hpp"
#include "task_state.hpp"

using namespace hal::task;

TEST(TaskState, DeterminedFromIoAndMotion)
{
    EXPECT_EQ(determine_state(true, true), TaskState::ESTOP);
    EXPECT_EQ(determine_state(true, false), TaskState::ESTOP);
    EXPECT_EQ(determine_state(false, false), TaskState::ESTOP_RESET);
    EXPECT_EQ(determine_state(false, true), TaskState::ON);
}

TEST(TaskState, StateRequests)
{
    EXPECT_EQ(check_state_request(TaskState::ESTOP, TaskState::ON, false, true), "");
    EXPECT_EQ(check_state_request(TaskState::OFF, TaskState::ESTOP, false, true), "");
    EXPECT_EQ(check_state_request(TaskState::ESTOP_RESET, TaskState::ESTOP, false, true),
              "cannot reset estop: iocontrol is not connected");
    EXPECT_EQ(check_state_request(TaskState::ESTOP_RESET, TaskState::ESTOP, true, true), "");
    EXPECT_EQ(check_state_request(TaskState::ON, TaskState::ESTOP, true, true),
              "cannot turn the machine on while in estop (reset estop first)");
    EXPECT_EQ(check_state_request(TaskState::ON, TaskState::ESTOP_RESET, true, false), "");
    EXPECT_EQ(parse_state("estop_reset"), TaskState::ESTOP_RESET);
    EXPECT_FALSE(parse_state("RESET"));
    EXPECT_EQ(parse_mode("mdi"), TaskMode::MDI);
}

TEST(TaskState, ModeChanges)
{
    EXPECT_EQ(check_mode_change(TaskMode::MANUAL, TaskMode::MDI, InterpState::IDLE, true),
              "Ignoring task mode change while jogging");
    EXPECT_EQ(check_mode_change(TaskMode::AUTO, TaskMode::MDI, InterpState::READING, false),
              "Can't switch mode while mode is AUTO and interpreter is not IDLE");
    EXPECT_EQ(check_mode_change(TaskMode::AUTO, TaskMode::AUTO, InterpState::READING, false), "");
    EXPECT_EQ(check_mode_change(TaskMode::MDI, TaskMode::MANUAL, InterpState::WAITING, false), "");
}

TEST(TaskState, CommandPreconditions)
{
    Situation s;
    s.state = TaskState::ON;
    s.mode = TaskMode::MANUAL;
    s.all_homed = true;
    EXPECT_EQ(check_command("MDI", s), "MDI: task is not in MDI mode");
    EXPECT_EQ(check_command("HOME", s), "");
    EXPECT_EQ(check_command("RUN", s), "RUN: task is not in AUTO mode");
    s.mode = TaskMode::MDI;
    EXPECT_EQ(check_command("MDI", s), "");
    EXPECT_EQ(check_command("HOME", s), "HOME: task is not in MANUAL mode");
    s.all_homed = false;
    EXPECT_EQ(check_command("MDI", s).rfind("MDI: machine is not homed", 0), 0u);
    s.no_force_homing = true;
    EXPECT_EQ(check_command("MDI", s), "");
    s.state = TaskState::ESTOP_RESET;
    EXPECT_EQ(check_command("MDI", s), "MDI: machine is not on");
    EXPECT_EQ(check_command("MIST", s), "");
    s.state = TaskState::ESTOP;
    EXPECT_EQ(check_command("MIST", s), "MIST: machine is in estop");
    EXPECT_EQ(check_command("ABORT", s), "");
    EXPECT_EQ(check_command("FEED_OVERRIDE", s), "");
    s = Situation{};
    s.state = TaskState::ON;
    s.mode = TaskMode::AUTO;
    s.all_homed = true;
    EXPECT_EQ(check_command("RUN", s), "RUN: no program is open");
    s.program_open = true;
    EXPECT_EQ(check_command("RUN", s), "");
    s.interp = InterpState::READING;
    EXPECT_EQ(check_command("RUN", s), "RUN: a program is already running");
    EXPECT_EQ(check_command("STEP", s), "");
    EXPECT_EQ(check_command("OPEN", s), "OPEN: the interpreter is not idle");
    s.interp = InterpState::IDLE;
    s.busy = true;
    EXPECT_EQ(check_command("RUN", s), "RUN: task is busy (waiting for motion in an interpreter call)");
}

static TaskConfig config_from(const std::string& text)
{
    auto ini = hal::ini::IniFile::parse(text, "/cfg/test.ini");
    EXPECT_TRUE(ini) << ini.error().message;
    auto c = read_task_config(*ini);
    EXPECT_TRUE(c) << c.error().message;
    return *c;
}

static const char* MILL = R"(
[TASK]
CYCLE_TIME = 0.01
[TRAJ]
COORDINATES = X Y Z
LINEAR_UNITS = inch
MAX_LINEAR_VELOCITY = 5
MAX_LINEAR_ACCELERATION = 100
[KINS]
JOINTS = 3
[AXIS_X]
MAX_VELOCITY = 4
MAX_ACCELERATION = 40
MIN_LIMIT = -10
MAX_LIMIT = 10
[AXIS_Y]
MAX_VELOCITY = 3
MAX_ACCELERATION = 30
[AXIS_Z]
MAX_VELOCITY = 1
MAX_ACCELERATION = 10
[JOINT_0]
MAX_VELOCITY = 5
HOME_OFFSET = 1.5
HOME_SEQUENCE = 1
HOME_USE_INDEX = YES
VOLATILE_HOME = 1
FERROR = 0.05
[JOINT_2]
TYPE = ANGULAR
)";

TEST(TaskConfig, ReadsTheKeys)
{
    TaskConfig c = config_from(MILL);
    EXPECT_DOUBLE_EQ(c.cycle_time, 0.01);
    EXPECT_EQ(c.joints, 3);
    EXPECT_EQ(c.linear_units, "inch");
    EXPECT_NEAR(c.units_per_mm, 1 / 25.4, 1e-12);
    EXPECT_TRUE(c.axis[0].present && c.axis[1].present && c.axis[2].present);
    EXPECT_FALSE(c.axis[3].present);
    EXPECT_DOUBLE_EQ(c.axis[0].min_limit, -10);
    EXPECT_DOUBLE_EQ(c.joint[0].home_offset, 1.5);
    EXPECT_EQ(c.joint[0].home_flags, 2);
    EXPECT_TRUE(c.joint[0].volatile_home);
    EXPECT_DOUBLE_EQ(c.joint[0].min_ferror, 0.05);   // MIN_FERROR defaults to FERROR
    EXPECT_EQ(c.joint[2].type, 2);
    EXPECT_EQ(c.joint[1].home_sequence, 999);
}

TEST(TaskConfig, ErrorsNameFileAndLine)
{
    auto ini = hal::ini::IniFile::parse("[KINS]\nJOINTS = 40\n", "/cfg/x.ini");
    ASSERT_TRUE(ini);
    auto c = read_task_config(*ini);
    ASSERT_FALSE(c);
    EXPECT_EQ(c.error().message, "/cfg/x.ini:2: [KINS]JOINTS: 40 out of range 1..16");
    ini = hal::ini::IniFile::parse("[TRAJ]\nCOORDINATES = X Q\n", "/cfg/x.ini");
    c = read_task_config(*ini);
    ASSERT_FALSE(c);
    EXPECT_EQ(c.error().message, "/cfg/x.ini:2: [TRAJ]COORDINATES: 'Q' is not one of X Y Z A B C U V W");
    ini = hal::ini::IniFile::parse("[JOINT_0]\nFERROR = abc\n", "/cfg/x.ini");
    c = read_task_config(*ini);
    ASSERT_FALSE(c);
    EXPECT_NE(c.error().message.find("/cfg/x.ini:2"), std::string::npos);
}

TEST(TaskConfig, StartupCommandsInOrder)
{
    TaskConfig c = config_from(MILL);
    auto cmds = motion_init_commands(c);
    ASSERT_TRUE(cmds);
    const auto& v = *cmds;
    ASSERT_GE(v.size(), 2u);
    EXPECT_EQ(v[0].command, MOTCMD_SET_NUM_JOINTS);
    EXPECT_EQ(v[0].count, 3);
    EXPECT_EQ(v[1].command, MOTCMD_SET_NUM_SPINDLES);
    int activates = 0, axis_vel = 0;
    bool homing_seen = false;
    for (const motion_command& m : v) {
        if (m.command == MOTCMD_JOINT_ACTIVATE)
            ++activates;
        if (m.command == MOTCMD_SET_AXIS_VEL_LIMIT) {
            ++axis_vel;
            if (m.axis == 1) {
                EXPECT_DOUBLE_EQ(m.value, 3);
            }
        }
        if (m.command == MOTCMD_SET_JOINT_HOMING_PARAMS && m.joint == 0) {
            homing_seen = true;
            EXPECT_DOUBLE_EQ(m.offset, 1.5);
            EXPECT_EQ(m.home_sequence, 1);
            EXPECT_EQ(m.volatile_home, 1);
            EXPECT_EQ(m.flags, 2);
        }
    }
    EXPECT_EQ(activates, 3);
    EXPECT_EQ(axis_vel, 3);
    EXPECT_TRUE(homing_seen);
    EXPECT_EQ(v.back().command, MOTCMD_SET_VEL);
}

namespace {
struct FakeHost : TaskCanon::Host {
    int probes = 0;
    rs274::ProbeResult probe_result() override
    {
        ++probes;
        rs274::ProbeResult r;
        r.position = {1, 2, -3};
        r.tripped = true;
        return r;
    }
    double wait_input(int, bool, rs274::WaitType, double) override { return 1; }
    int user_m_code(int, const std::string&, double, double) override { return 0; }
    bool hal_value(const std::string&, double&) override { return false; }
};
}  // namespace

TEST(TaskCanon, LineLimitsFollowTheAxes)
{
    TaskConfig c = config_from(MILL);
    FakeHost h;
    TaskCanon canon(c, h);
    double vel, acc;
    canon.line_limits({0, 0, 0}, {10, 0, 0}, vel, acc);
    EXPECT_DOUBLE_EQ(vel, 4);
    EXPECT_DOUBLE_EQ(acc, 40);
    canon.line_limits({0, 0, 0}, {0, 0, -1}, vel, acc);
    EXPECT_DOUBLE_EQ(vel, 1);
    // 3-4-5 move in XY: X would need 3/5 of the speed, Y 4/5: Y (3 max) limits at 3.75
    canon.line_limits({0, 0, 0}, {3, 4, 0}, vel, acc);
    EXPECT_DOUBLE_EQ(vel, 3.0 * 5 / 4);
    // the [TRAJ] cap
    TaskConfig fast = c;
    fast.max_vel = 2;
    TaskCanon capped(fast, h);
    capped.line_limits({0, 0, 0}, {10, 0, 0}, vel, acc);
    EXPECT_DOUBLE_EQ(vel, 2);
}

TEST(TaskCanon, MovesBecomeMotionCommands)
{
    TaskConfig c = config_from(MILL);
    FakeHost h;
    TaskCanon canon(c, h);
    canon.block_begin("p.ngc", 7);
    canon.set_feed_rate(60);   // 60 units/min = 1 unit/s
    canon.straight_feed({2, 0, 0});
    canon.block_begin("p.ngc", 8);
    canon.straight_traverse({2, 3, 0});
    canon.block_begin("p.ngc", 9);
    canon.arc_feed(4, 3, 3, 3, -1, {4, 3, -0.5});
    auto& q = canon.queue();
    ASSERT_EQ(q.size(), 3u);
    EXPECT_EQ(q[0].cmd.command, MOTCMD_SET_LINE);
    EXPECT_EQ(q[0].cmd.motion_type, MOTION_TYPE_FEED);
    EXPECT_EQ(q[0].cmd.id, 7);
    EXPECT_DOUBLE_EQ(q[0].cmd.vel, 1);
    EXPECT_DOUBLE_EQ(q[0].cmd.ini_maxvel, 4);
    EXPECT_DOUBLE_EQ(q[0].cmd.pos.v[0], 2);
    EXPECT_EQ(q[1].cmd.motion_type, MOTION_TYPE_TRAVERSE);
    EXPECT_DOUBLE_EQ(q[1].cmd.vel, 3);   // a Y-only rapid: Y's limit
    const motion_command& a = q[2].cmd;
    EXPECT_EQ(a.command, MOTCMD_SET_CIRCLE);
    EXPECT_EQ(a.id, 9);
    EXPECT_DOUBLE_EQ(a.center[0], 3);
    EXPECT_DOUBLE_EQ(a.center[1], 3);
    EXPECT_DOUBLE_EQ(a.normal[2], -1);   // clockwise
    EXPECT_EQ(a.turn, 0);
    EXPECT_DOUBLE_EQ(a.pos.v[2], -0.5);
    EXPECT_DOUBLE_EQ(a.ini_maxvel, 1);   // the helix axis Z moves: its 1 unit/s
}

TEST(TaskCanon, SynchronisedItems)
{
    TaskConfig c = config_from(MILL);
    FakeHost h;
    TaskCanon canon(c, h);
    canon.set_spindle_speed(0, 1000);
    canon.start_spindle_clockwise(0);
    canon.mist_on();
    canon.select_tool(3);
    canon.change_tool(3);
    canon.dwell(0.5);
    canon.message("hello");
    canon.program_stop();
    canon.program_end();
    auto& q = canon.queue();
    ASSERT_EQ(q.size(), 8u);
    EXPECT_EQ(q[0].cmd.command, MOTCMD_SPINDLE_ON);
    EXPECT_DOUBLE_EQ(q[0].cmd.vel, 1000);
    EXPECT_TRUE(q[0].wait_motion);
    EXPECT_EQ(q[1].kind, Item::Io);
    EXPECT_EQ(q[1].io, (std::vector<std::string>{"MIST", "1"}));
    EXPECT_EQ(q[2].io, (std::vector<std::string>{"TOOL_PREPARE", "3"}));
    EXPECT_FALSE(q[2].wait_motion);   // a prepare runs while the machine moves
    EXPECT_EQ(q[3].io, (std::vector<std::string>{"TOOL_LOAD"}));
    EXPECT_TRUE(q[3].wait_motion);
    EXPECT_EQ(q[4].kind, Item::Delay);
    EXPECT_DOUBLE_EQ(q[4].seconds, 0.5);
    EXPECT_EQ(q[5].kind, Item::Message);
    EXPECT_EQ(q[5].text, "hello");
    EXPECT_EQ(q[6].kind, Item::Stop);
    EXPECT_EQ(q[7].kind, Item::End);
}

TEST(TaskCanon, ProbeAsksTheHostAndSkipModeQueuesNothing)
{
    TaskConfig c = config_from(MILL);
    FakeHost h;
    TaskCanon canon(c, h);
    canon.straight_probe({0, 0, -5}, rs274::ProbeType::G38_2);
    auto r = canon.probe_result();
    EXPECT_EQ(h.probes, 1);
    EXPECT_TRUE(r.tripped);
    EXPECT_DOUBLE_EQ(canon.position()[2], -3);   // the next move starts where it tripped
    auto& q = canon.queue();
    ASSERT_EQ(q.size(), 2u);
    EXPECT_EQ(q[0].cmd.command, MOTCMD_CLEAR_PROBE_FLAGS);
    EXPECT_EQ(q[1].cmd.command, MOTCMD_PROBE);
    q.clear();
    canon.set_skip(true);
    canon.straight_feed({1, 1, 1});
    canon.straight_probe({0, 0, -5}, rs274::ProbeType::G38_2);
    canon.probe_result();
    EXPECT_EQ(h.probes, 1);
    EXPECT_TRUE(q.empty());
}

TEST(TaskCanon, ThroughTheInterpreter)
{
    TaskConfig c = config_from(MILL);
    FakeHost h;
    TaskCanon canon(c, h);
    rs274::Config ic;
    ic.machine_units = rs274::Units::INCH;
    rs274::Interp in(canon, ic);
    ASSERT_TRUE(in.init()) << in.error().to_string();
    canon.queue().clear();
    ASSERT_TRUE(in.open_text("t.ngc", "G20 G90 G64 P0.001\nG0 X1 Y1\nG1 X2 F30\nM8\nM2\n"));
    while (in.step() == rs274::Status::OK) {
    }
    std::vector<int> lines, cmds;
    for (const Item& it : canon.queue()) {
        if (it.kind == Item::Motion && (it.cmd.command == MOTCMD_SET_LINE || it.cmd.command == MOTCMD_SET_TERM_COND)) {
            lines.push_back(it.line);
            cmds.push_back(it.cmd.command);
        }
    }
    ASSERT_GE(cmds.size(), 3u);
    EXPECT_EQ(cmds[0], MOTCMD_SET_TERM_COND);
    EXPECT_EQ(lines[1], 2);
    EXPECT_EQ(lines[2], 3);
    const Item* feed = nullptr;
    bool flood = false, end = false;
    for (const Item& it : canon.queue()) {
        if (it.kind == Item::Motion && it.cmd.command == MOTCMD_SET_LINE && it.cmd.motion_type == MOTION_TYPE_FEED)
            feed = &it;
        flood |= it.kind == Item::Io && it.io[0] == "FLOOD";
        end |= it.kind == Item::End;
    }
    ASSERT_TRUE(feed);
    EXPECT_DOUBLE_EQ(feed->cmd.vel, 0.5);   // F30 inch/min
    EXPECT_DOUBLE_EQ(feed->cmd.pos.v[0], 2);
    EXPECT_TRUE(flood);
    EXPECT_TRUE(end);
}
