// SPDX-License-Identifier: GPL-2.0-or-later
// emcrsh sessions against a fake machine: the protocol's replies (with their line
// ends), permissions, enable between two sessions, every subcommand's reply format
// from a status map and the bus commands SET sends.
#include <gtest/gtest.h>

#include <regex>

#include "session.hpp"

using namespace hal::emcrsh;

namespace {

struct FakeMachine : Machine {
    std::vector<std::pair<std::string, Wait>> sent;
    std::vector<std::pair<Wait, double>> waits;
    hal::bus::Status st;
    std::vector<hal::bus::Message> msgs;
    std::string refuse;   // a bus verb answered with an error
    bool no_bus = false;

    hal::Result<void> command(const std::string& line, Wait wait, double) override
    {
        sent.emplace_back(line, wait);
        if (!refuse.empty() && line.rfind(refuse, 0) == 0)
            return hal::Error{-1, refuse + ": refused"};
        return hal::ok();
    }
    hal::Result<void> wait_last(Wait wait, double t) override
    {
        waits.emplace_back(wait, t);
        return hal::ok();
    }
    hal::Result<hal::bus::Status> status() override
    {
        if (no_bus)
            return hal::Error{-1, "no bus"};
        return st;
    }
    std::vector<hal::bus::Message> take_messages() override
    {
        auto m = std::move(msgs);
        msgs.clear();
        return m;
    }
};

hal::bus::Status mill_status()
{
    hal::bus::Status s;
    s["task.state"] = "ON";
    s["task.mode"] = "MDI";
    s["task.interp"] = "IDLE";
    s["task.paused"] = "0";
    s["task.file"] = "";
    s["task.line"] = "0";
    s["task.motion_line"] = "0";
    s["task.debug"] = "0";
    s["task.optional_stop"] = "1";
    s["task.program_units"] = "MM";
    s["task.feed_rate"] = "600.000000";
    s["task.spindle_speed"] = "-1000.000000";
    s["task.g5x_offset"] = "1.000000 2.000000 3.000000";
    s["task.g92_offset"] = "0.500000 0.000000 0.000000";
    s["task.tool_offset"] = "0.000000 0.000000 12.500000";
    s["task.active_gcodes"] = "G1 G17 G40 G21 G90 G94 G54 G49 G99 G64 G97 G91.1 G8";
    s["traj.axes"] = "XYZ";
    s["traj.joints"] = "3";
    s["traj.spindles"] = "1";
    s["traj.units_per_mm"] = "1.000000";
    s["traj.angular_units"] = "degree";
    s["traj.mode"] = "COORD";
    s["traj.feed_scale"] = "1.200000";
    s["traj.kinematics_type"] = "1";
    s["traj.probe_tripped"] = "0";
    s["traj.probe_val"] = "1";
    s["axis.x.pos_cmd"] = "10.000000";
    s["axis.y.pos_cmd"] = "5.000000";
    s["axis.z.pos_cmd"] = "-2.000000";
    s["axis.x.pos_fb"] = "9.999000";
    s["axis.y.pos_fb"] = "5.000000";
    s["axis.z.pos_fb"] = "-2.000000";
    for (int j = 0; j < 3; ++j) {
        std::string p = "joint." + std::to_string(j) + ".";
        s[p + "type"] = "LINEAR";
        s[p + "homed"] = j == 2 ? "0" : "1";
        s[p + "fault"] = j == 1 ? "1" : "0";
        s[p + "pos_fb"] = std::to_string(j) + ".500000";
        s[p + "min_hard_limit"] = "0";
        s[p + "max_hard_limit"] = j == 2 ? "1" : "0";
        s[p + "min_soft_limit"] = j == 1 ? "1" : "0";
        s[p + "max_soft_limit"] = "0";
        s[p + "override_limits"] = "0";
    }
    s["spindle.0.direction"] = "-1";
    s["spindle.0.enabled"] = "1";
    s["spindle.0.brake"] = "0";
    s["spindle.0.override"] = "0.850000";
    s["io.mist"] = "1";
    s["io.flood"] = "0";
    s["io.lube"] = "1";
    s["io.lube_level"] = "1";
    s["io.tool_in_spindle"] = "2";
    return s;
}

struct EmcrshSession : ::testing::Test {
    Shared shared{Options{}};
    FakeMachine m;
    Session s{1, shared, m};
    void SetUp() override { m.st = mill_status(); }
    void hello_enable()
    {
        ASSERT_EQ(s.handle("hello EMC test 1.0"), "HELLO ACK EMCNETSVR 1.1\r\n");
        ASSERT_EQ(s.handle("set echo off"), "set echo off\r\n");
        ASSERT_EQ(s.handle("set enable EMCTOO"), "");
    }
    std::string get(const std::string& sub) { return s.handle("get " + sub); }
};

}  // namespace

TEST(EmcrshSubcommands, SeventySixInTheReferenceOrder)
{
    EXPECT_EQ(subcommands().size(), 76u);
    EXPECT_EQ(subcommand_index("ECHO"), 0);
    EXPECT_LT(subcommand_index("COMM_PROT"), subcommand_index("INIFILE"));
    EXPECT_EQ(subcommand_index("SET_TIMEOUT"), subcommand_index("TIMEOUT"));
    EXPECT_EQ(subcommand_index("FLY"), -1);
}

TEST_F(EmcrshSession, HelloAndEcho)
{
    EXPECT_EQ(s.handle("hello wrong test 1.0"), "HELLO NAK\r\n");
    EXPECT_EQ(s.handle("hello EMC test"), "HELLO NAK\r\n");
    EXPECT_EQ(s.handle("set echo off"), "SET NAK\r\n");   // not linked
    EXPECT_EQ(s.handle("hello EMC test 1.0"), "HELLO ACK EMCNETSVR 1.1\r\n");
    EXPECT_EQ(s.handle("get echo"), "get echo\r\nECHO ON\r\n");
    EXPECT_EQ(s.handle("fly away"), "fly away\r\n");   // unknown: only the echo
    EXPECT_EQ(s.handle("set echo off"), "set echo off\r\n");
    EXPECT_EQ(s.handle("fly away"), "");
    EXPECT_EQ(get("echo"), "ECHO OFF\r\n");
    EXPECT_EQ(s.handle("   "), "");
}

TEST_F(EmcrshSession, GetWorksWithoutHelloAndNaks)
{
    EXPECT_EQ(get("plat"), "PLAT Linux\r\n");
    EXPECT_EQ(s.handle("get"), "GET NAK\r\n");
    EXPECT_EQ(get("nonsense"), "GET NAK\r\n");
    EXPECT_EQ(get("mdi"), "GET MDI NAK\r\n\r\n");
    EXPECT_EQ(get("home"), "GET HOME NAK\r\n\r\n");
    EXPECT_EQ(get("abs_cmd_pos 9"), "GET ABS_CMD_POS NAK\r\n\r\n");
    m.no_bus = true;
    EXPECT_EQ(get("estop"), "GET ESTOP NAK\r\n\r\n");
}

TEST_F(EmcrshSession, SetPermissionsAndVerbose)
{
    ASSERT_EQ(s.handle("hello EMC test 1.0"), "HELLO ACK EMCNETSVR 1.1\r\n");
    s.handle("set echo off");
    EXPECT_EQ(s.handle("set mode mdi"), "SET MODE NAK\n\r");   // not enabled
    EXPECT_TRUE(m.sent.empty());
    EXPECT_EQ(s.handle("set enable wrong"), "SET ENABLE NAK\n\r");
    EXPECT_EQ(s.handle("set enable emctoo"), "SET ENABLE NAK\n\r");   // case-sensitive
    EXPECT_EQ(s.handle("set verbose on"), "SET VERBOSE ACK\n\r");
    EXPECT_EQ(s.handle("set enable EMCTOO"), "SET ENABLE ACK\n\r");
    EXPECT_EQ(get("enable"), "ENABLE ON\r\n");
    EXPECT_EQ(s.handle("set mode mdi"), "SET MODE ACK\n\r");
    EXPECT_EQ(s.handle("set mode fast"), "SET MODE NAK\n\r");
    EXPECT_EQ(s.handle("set tool 3"), "SET TOOL NAK\n\r");   // read-only
    EXPECT_EQ(s.handle("set fly 3"), "SET NAK\r\n");
    EXPECT_EQ(s.handle("set"), "SET NAK\r\n");
    EXPECT_EQ(s.handle("set enable off"), "SET ENABLE ACK\n\r");
    EXPECT_EQ(get("enable"), "ENABLE OFF\r\n");
}

TEST_F(EmcrshSession, EnableMovesToTheLastSessionThatAsks)
{
    FakeMachine m2;
    Session s2(2, shared, m2);
    hello_enable();
    EXPECT_TRUE(s.enabled());
    s2.handle("hello EMC other 1.0");
    s2.handle("set echo off");
    EXPECT_EQ(s2.handle("set enable EMCTOO"), "");
    EXPECT_FALSE(s.enabled());
    EXPECT_TRUE(s2.enabled());
    EXPECT_EQ(s.handle("set mode mdi"), "SET MODE NAK\n\r");
    EXPECT_EQ(s.handle("shutdown"), "SHUTDOWN NAK\r\n");
    EXPECT_FALSE(shared.shutdown);
    EXPECT_EQ(s.handle("set enable off"), "");   // not its to give up
    EXPECT_TRUE(s2.enabled());
    EXPECT_EQ(s2.handle("shutdown"), "");
    EXPECT_TRUE(shared.shutdown);
    EXPECT_TRUE(s2.closing());
}

TEST_F(EmcrshSession, ClosingSessionGivesEnableUp)
{
    {
        FakeMachine m2;
        Session s2(2, shared, m2);
        s2.handle("hello EMC other 1.0");
        s2.handle("set enable EMCTOO");
        EXPECT_EQ(shared.enabled.load(), 2);
    }
    EXPECT_EQ(shared.enabled.load(), 0);
}

TEST_F(EmcrshSession, QuitCloses)
{
    EXPECT_EQ(s.handle("quit"), "");
    EXPECT_TRUE(s.closing());
}

TEST_F(EmcrshSession, SetSendsBusCommands)
{
    hello_enable();
    const std::pair<const char*, const char*> cases[] = {
        {"set estop off", "STATE ESTOP_RESET"},
        {"set estop on", "STATE ESTOP"},
        {"set machine on", "STATE ON"},
        {"set machine off", "STATE OFF"},
        {"set mode manual", "MODE MANUAL"},
        {"set mist on", "MIST ON"},
        {"set flood off", "FLOOD OFF"},
        {"set lube on", "LUBE ON"},
        {"set spindle forward", "SPINDLE FORWARD 1000 -1"},
        {"set spindle 0 reverse", "SPINDLE REVERSE 1000 0"},
        {"set spindle off", "SPINDLE OFF 0 -1"},
        {"set spindle increase", "SPINDLE INCREASE 0 -1"},
        {"set brake on", "BRAKE ON -1"},
        {"set brake 0 off", "BRAKE OFF 0"},
        {"set tool_offset 2 12.5 6", "TOOL_OFFSET 2 12.5 6"},
        {"set load_tool_table /tmp/My.tbl", "LOAD_TOOL_TABLE /tmp/My.tbl"},
        {"set home -1", "HOME -1"},
        {"set home 2", "HOME 2"},
        {"set jog 0 600", "JOG_CONT 0 10"},
        {"set jog x -60", "JOG_CONT X -1"},
        {"set jog_incr 1 120 0.5", "JOG_INCR 1 2 0.5"},
        {"set jog_stop 1", "JOG_STOP 1"},
        {"set feed_override 120", "FEED_OVERRIDE 1.2"},
        {"set feed_override -5", "FEED_OVERRIDE 0"},
        {"set spindle_override 50", "SPINDLE_OVERRIDE 0.5 -1"},
        {"set spindle_override 0 80", "SPINDLE_OVERRIDE 0.8 0"},
        {"set mdi G0 X1  Y2", "MDI G0 X1  Y2"},
        {"set task_plan_init", "PLAN_INIT"},
        {"set open /tmp/Prog.ngc", "OPEN /tmp/Prog.ngc"},
        {"set run 5", "RUN 5"},
        {"set pause", "PAUSE"},
        {"set resume", "RESUME"},
        {"set step", "STEP"},
        {"set abort", "ABORT"},
        {"set probe_clear", "PROBE_CLEAR"},
        {"set probe 1 2 -3", "MDI G38.3 X1 Y2 Z-3"},
        {"set teleop_enable on", "TELEOP 1"},
        {"set teleop_enable off", "TELEOP 0"},
        {"set override_limits on", "OVERRIDE_LIMITS 0"},
        {"set override_limits off", "OVERRIDE_LIMITS -1"},
        {"set optional_stop 1", "OPTIONAL_STOP 1"},
        {"set debug 3", "DEBUG 3"},
    };
    for (const auto& [line, bus] : cases) {
        m.sent.clear();
        EXPECT_EQ(s.handle(line), "") << line;
        ASSERT_FALSE(m.sent.empty()) << line;
        EXPECT_EQ(m.sent.back().first, bus) << line;
        EXPECT_EQ(m.sent.back().second, Wait::RECEIVED) << line;
    }
}

TEST_F(EmcrshSession, SetNaksBadArgumentsWithoutSending)
{
    hello_enable();
    const char* bad[] = {"set estop maybe", "set spindle sideways", "set spindle", "set brake 0",
                         "set tool_offset 2 x 6", "set tool_offset 2 1", "set home", "set home x",
                         "set jog 0", "set jog q 10", "set jog_incr 0 10", "set feed_override lots",
                         "set mdi", "set open", "set run -1", "set probe 1 2", "set teleop_enable maybe",
                         "set optional_stop 2", "set debug high", "set load_tool_table",
                         "set spindle_override", "set mode"};
    for (const char* line : bad) {
        m.sent.clear();
        std::string sub = upper(split_words(line)[1]);
        EXPECT_EQ(s.handle(line), "SET " + sub + " NAK\n\r") << line;
        EXPECT_TRUE(m.sent.empty()) << line;
    }
}

TEST_F(EmcrshSession, RefusedCommandIsNakAndTheErrorIsKept)
{
    hello_enable();
    m.refuse = "MDI";
    EXPECT_EQ(s.handle("set mdi g0 x1"), "SET MDI NAK\n\r");
    EXPECT_EQ(get("error"), "ERROR MDI: refused\r\n");
    EXPECT_EQ(get("error"), "ERROR OK\r\n");
}

TEST_F(EmcrshSession, WaitsTimeoutUpdate)
{
    hello_enable();
    EXPECT_EQ(get("set_wait"), "SET_WAIT RECEIVED\r\n");
    EXPECT_EQ(s.handle("set set_wait done"), "");
    EXPECT_EQ(get("set_wait"), "SET_WAIT DONE\r\n");
    s.handle("set mode mdi");
    EXPECT_EQ(m.sent.back().second, Wait::DONE);
    EXPECT_EQ(s.handle("set set_wait none"), "");
    s.handle("set mode auto");
    EXPECT_EQ(m.sent.back().second, Wait::NONE);
    EXPECT_EQ(s.handle("set set_wait sometimes"), "SET SET_WAIT NAK\n\r");
    EXPECT_EQ(s.handle("set timeout 2.5"), "");
    EXPECT_EQ(get("timeout"), "SET_TIMEOUT 2.500000\r\n");
    EXPECT_EQ(s.handle("set wait done"), "");
    ASSERT_EQ(m.waits.size(), 1u);
    EXPECT_EQ(m.waits[0].first, Wait::DONE);
    EXPECT_DOUBLE_EQ(m.waits[0].second, 2.5);
    EXPECT_EQ(s.handle("set wait later"), "SET WAIT NAK\n\r");
    EXPECT_EQ(get("wait"), "GET WAIT NAK\r\n\r\n");
    // UPDATE NONE: GETs answer from the status read last
    EXPECT_EQ(get("mode"), "MODE MDI\r\n");
    EXPECT_EQ(s.handle("set update none"), "");
    m.st["task.mode"] = "AUTO";
    EXPECT_EQ(get("mode"), "MODE MDI\r\n");
    EXPECT_EQ(s.handle("set update auto"), "");
    EXPECT_EQ(get("mode"), "MODE AUTO\r\n");
}

TEST_F(EmcrshSession, SessionSettings)
{
    hello_enable();
    EXPECT_EQ(get("verbose"), "VERBOSE OFF\r\n");
    EXPECT_EQ(get("config"), "CONFIG\r\n");
    EXPECT_EQ(get("comm_mode"), "COMM_MODE ASCII\r\n");
    EXPECT_EQ(s.handle("set comm_mode binary"), "");
    EXPECT_EQ(get("comm_mode"), "COMM_MODE BINARY\r\n");
    EXPECT_EQ(get("comm_prot"), "COMM_PROT 1.0\r\n");
    EXPECT_EQ(s.handle("set comm_prot 1.1"), "");
    EXPECT_EQ(get("comm_prot"), "COMM_PROT 1.1\r\n");
    EXPECT_EQ(s.handle("set comm_prot 2.0"), "SET COMM_PROT NAK\n\r");
    EXPECT_EQ(s.handle("set config x"), "");
    EXPECT_EQ(get("linear_unit_conversion"), "LINEAR_UNIT_CONVERSION AUTO\r\n");
    EXPECT_EQ(s.handle("set linear_unit_conversion inch"), "");
    EXPECT_EQ(get("display_linear_units"), "DISPLAY_LINEAR_UNITS INCH\r\n");
    EXPECT_EQ(s.handle("set angular_unit_conversion rad"), "");
    EXPECT_EQ(get("angular_unit_conversion"), "ANGULAR_UNIT_CONVERSION RAD\r\n");
    EXPECT_EQ(get("display_angular_units"), "DISPLAY_ANGULAR_UNITS RAD\r\n");
    EXPECT_EQ(s.handle("set linear_unit_conversion furlong"), "SET LINEAR_UNIT_CONVERSION NAK\n\r");
}

TEST_F(EmcrshSession, MachineStatusReplies)
{
    EXPECT_EQ(get("estop"), "ESTOP OFF\r\n");
    EXPECT_EQ(get("machine"), "MACHINE ON\r\n");
    EXPECT_EQ(get("mode"), "MODE MDI\r\n");
    EXPECT_EQ(get("mist"), "MIST ON\r\n");
    EXPECT_EQ(get("flood"), "FLOOD OFF\r\n");
    EXPECT_EQ(get("lube"), "LUBE ON\r\n");
    EXPECT_EQ(get("lube_level"), "LUBE_LEVEL OK\r\n");
    EXPECT_EQ(get("spindle"), "SPINDLE 0 REVERSE\r\n");
    EXPECT_EQ(get("spindle 0"), "SPINDLE 0 REVERSE\r\n");
    EXPECT_EQ(get("spindle 1"), "GET SPINDLE NAK\r\n\r\n");
    EXPECT_EQ(get("brake"), "BRAKE OFF\r\n");
    EXPECT_EQ(get("tool"), "TOOL 2\r\n");
    EXPECT_EQ(get("tool_offset"), "TOOL_OFFSET 12.500000\r\n");
    EXPECT_EQ(get("feed_override"), "FEED_OVERRIDE 120\r\n");
    EXPECT_EQ(get("spindle_override"), "SPINDLE_OVERRIDE 0 85\r\n");
    EXPECT_EQ(get("program"), "PROGRAM NONE\r\n");
    EXPECT_EQ(get("program_status"), "PROGRAM_STATUS IDLE\r\n");
    EXPECT_EQ(get("program_line"), "PROGRAM_LINE 0\r\n");
    EXPECT_EQ(get("program_codes"),
              "PROGRAM_CODES G1 G17 G40 G21 G90 G94 G54 G49 G99 G64 G97 G91.1 G8 F600 S1000\r\n");
    EXPECT_EQ(get("probe_tripped"), "PROBE_TRIPPED 0\r\n");
    EXPECT_EQ(get("probe_value"), "PROBE_VALUE 1\r\n");
    EXPECT_EQ(get("teleop_enable"), "TELEOP_ENABLE NO\r\n");
    EXPECT_EQ(get("kinematics_type"), "KINEMATICS_TYPE 1\r\n");
    EXPECT_EQ(get("override_limits"), "OVERRIDE_LIMITS 0\r\n");
    EXPECT_EQ(get("optional_stop"), "OPTIONAL_STOP 1\r\n");
    EXPECT_EQ(get("debug"), "DEBUG 0\r\n");
    m.st["task.state"] = "ESTOP";
    m.st["task.interp"] = "READING";
    m.st["task.file"] = "/tmp/p.ngc";
    m.st["task.line"] = "12";
    m.st["task.motion_line"] = "9";
    EXPECT_EQ(get("estop"), "ESTOP ON\r\n");
    EXPECT_EQ(get("machine"), "MACHINE OFF\r\n");
    EXPECT_EQ(get("program"), "PROGRAM /tmp/p.ngc\r\n");
    EXPECT_EQ(get("program_status"), "PROGRAM_STATUS RUNNING\r\n");
    EXPECT_EQ(get("program_line"), "PROGRAM_LINE 9\r\n");
    m.st["task.paused"] = "1";
    EXPECT_EQ(get("program_status"), "PROGRAM_STATUS PAUSED\r\n");
}

TEST_F(EmcrshSession, Positions)
{
    EXPECT_EQ(get("abs_cmd_pos"), "ABS_CMD_POS 10.000000 5.000000 -2.000000 0.000000 0.000000 0.000000\r\n");
    EXPECT_EQ(get("abs_act_pos 0"), "ABS_ACT_POS 0 9.999000\r\n");
    EXPECT_EQ(get("rel_cmd_pos"), "REL_CMD_POS 8.500000 3.000000 -5.000000 0.000000 0.000000 0.000000\r\n");
    EXPECT_EQ(get("rel_act_pos 2"), "REL_ACT_POS 2 -5.000000\r\n");
    EXPECT_EQ(get("pos_offset"), "POS_OFFSET 1.500000 2.000000 3.000000 0.000000 0.000000 0.000000\r\n");
    EXPECT_EQ(get("pos_offset x"), "POS_OFFSET X  1.500000\r\n");
    EXPECT_EQ(get("pos_offset R"), "POS_OFFSET R  0.000000\r\n");
    EXPECT_EQ(get("pos_offset q"), "GET POS_OFFSET NAK\r\n\r\n");
    hello_enable();
    EXPECT_EQ(s.handle("set linear_unit_conversion cm"), "");
    EXPECT_EQ(get("pos_offset y"), "POS_OFFSET Y  0.200000\r\n");
}

TEST_F(EmcrshSession, Joints)
{
    EXPECT_EQ(get("joint_pos"), "JOINT_POS 0.500000 1.500000 2.500000\r\n");
    EXPECT_EQ(get("joint_pos 1"), "JOINT_POS 1 1.500000\r\n");
    EXPECT_EQ(get("joint_pos 3"), "GET JOINT_POS NAK\r\n\r\n");
    EXPECT_EQ(get("joint_limit"), "JOINT_LIMIT OK MINSOFT MAXHARD\r\n");
    EXPECT_EQ(get("joint_fault"), "JOINT_FAULT OK FAULT OK\r\n");
    EXPECT_EQ(get("joint_homed"), "JOINT_HOMED YES YES NO\r\n");
    EXPECT_EQ(get("joint_homed 2"), "JOINT_HOMED 2 NO\r\n");
    EXPECT_EQ(get("joint_type"), "JOINT_TYPE LINEAR LINEAR LINEAR\r\n");
    EXPECT_EQ(get("joint_units 0"), "JOINT_UNITS 0 MM\r\n");
}

TEST_F(EmcrshSession, Units)
{
    EXPECT_EQ(get("program_units"), "PROGRAM_UNITS MM\r\n");
    EXPECT_EQ(get("program_linear_units"), "PROGRAM_LINEAR_UNITS MM\r\n");
    EXPECT_EQ(get("program_angular_units"), "PROGRAM_ANGULAR_UNITS DEG\r\n");
    EXPECT_EQ(get("user_linear_units"), "USER_LINEAR_UNITS MM\r\n");
    EXPECT_EQ(get("user_angular_units"), "USER_ANGULAR_UNITS DEG\r\n");
    EXPECT_EQ(get("display_linear_units"), "DISPLAY_LINEAR_UNITS MM\r\n");
    EXPECT_EQ(get("display_angular_units"), "DISPLAY_ANGULAR_UNITS DEG\r\n");
    m.st["task.program_units"] = "INCH";
    EXPECT_EQ(get("display_linear_units"), "DISPLAY_LINEAR_UNITS INCH\r\n");
}

TEST_F(EmcrshSession, OperatorMessagesAndTime)
{
    m.msgs = {{"DISPLAY", "tool 3 please"}, {"ERROR", "Z limit"}, {"TEXT", "hello"}, {"ERROR", "X limit"}};
    EXPECT_EQ(get("error"), "ERROR X limit\r\n");
    EXPECT_EQ(get("error"), "ERROR OK\r\n");
    EXPECT_EQ(get("operator_display"), "OPERATOR_DISPLAY tool 3 please\r\n");
    EXPECT_EQ(get("operator_text"), "OPERATOR_TEXT hello\r\n");
    EXPECT_EQ(get("operator_text"), "OPERATOR_TEXT OK\r\n");
    EXPECT_TRUE(std::regex_match(get("time"), std::regex("TIME [0-9]+\\.[0-9]{6}\r\n")));
}

TEST_F(EmcrshSession, RunReopensTheLastProgram)
{
    hello_enable();
    s.handle("set open /tmp/a.ngc");
    m.sent.clear();
    s.handle("set run");   // status: no file open
    ASSERT_EQ(m.sent.size(), 2u);
    EXPECT_EQ(m.sent[0].first, "OPEN /tmp/a.ngc");
    EXPECT_EQ(m.sent[1].first, "RUN");
    m.st["task.file"] = "/tmp/a.ngc";
    m.sent.clear();
    s.handle("set run 3");
    ASSERT_EQ(m.sent.size(), 1u);
    EXPECT_EQ(m.sent[0].first, "RUN 3");
}

TEST_F(EmcrshSession, HelpLinesEndLfCr)
{
    std::string h = s.handle("help");
    EXPECT_EQ(h.rfind("Available commands:\n\r", 0), 0u);
    EXPECT_NE(h.find("PROGRAM_CODES"), std::string::npos);
    EXPECT_EQ(s.handle("help hello").rfind("Usage: HELLO", 0), 0u);
}
