// SPDX-License-Identifier: GPL-2.0-or-later
// io_test.cpp - iocontrol without HAL: the tool table file and the cycle logic
// (estop pins, tool prepare/change handshakes for random and non-random changers).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "io_core.hpp"
#include "tooltable.hpp"

using namespace hal::io;

TEST(ToolTable, ParsesFieldsAnyOrder)
{
    auto t = parse_tool_line("P3 T12 Z-1.5 D6 x0.25 Q2 ;a remark; with semicolon");
    ASSERT_TRUE(t) << t.error().message;
    ASSERT_TRUE(*t);
    const Tool& tool = **t;
    EXPECT_EQ(tool.toolno, 12);
    EXPECT_EQ(tool.pocket, 3);
    EXPECT_DOUBLE_EQ(tool.offset[2], -1.5);
    EXPECT_DOUBLE_EQ(tool.offset[0], 0.25);
    EXPECT_DOUBLE_EQ(tool.diameter, 6);
    EXPECT_EQ(tool.orientation, 2);
    EXPECT_EQ(tool.comment, "a remark; with semicolon");
    EXPECT_EQ(format_tool(tool), "T12 P3 X+0.250000 Z-1.500000 D+6.000000 Q2 ;a remark; with semicolon");
    auto blank = parse_tool_line("   ;only a remark");
    ASSERT_TRUE(blank);
    EXPECT_FALSE(*blank);
}

TEST(ToolTable, RefusesBadLines)
{
    EXPECT_EQ(parse_tool_line("T1 P1 K3").error().message, "unknown field 'K3'");
    EXPECT_EQ(parse_tool_line("T1 P1 Zabc").error().message, "bad value in 'Zabc'");
    EXPECT_EQ(parse_tool_line("P1 Z1").error().message, "no tool number (T)");
    EXPECT_EQ(parse_tool_line("T4 Z1").error().message, "no pocket (P) for tool 4");
    EXPECT_EQ(parse_tool_line("T1 P1001").error().message, "bad value in 'P1001'");
    EXPECT_EQ(parse_tool_line("T1 P1 Q10").error().message, "bad value in 'Q10'");
    EXPECT_FALSE(parse_tool_line("T1 P1 ;" + std::string(300, 'x')));
}

static std::string scratch(const std::string& content)
{
    char tmpl[] = "/tmp/io_test.XXXXXX";
    int fd = mkstemp(tmpl);
    EXPECT_GE(fd, 0);
    std::string s = content;
    EXPECT_EQ(write(fd, s.data(), s.size()), static_cast<ssize_t>(s.size()));
    close(fd);
    return tmpl;
}

static std::string slurp(const std::string& path)
{
    std::ifstream f(path);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

TEST(ToolTable, FileRoundTripAndErrors)
{
    std::string p = scratch("; header\nT1 P1 Z10 D6 ;end mill\n\nT2 P2 Z20\n");
    auto tools = read_tool_file(p);
    ASSERT_TRUE(tools) << tools.error().message;
    ASSERT_EQ(tools->size(), 2u);
    ASSERT_TRUE(write_tool_file(p, *tools));
    EXPECT_EQ(slurp(p), "T1 P1 Z+10.000000 D+6.000000 ;end mill\nT2 P2 Z+20.000000\n");
    unlink(p.c_str());
    std::string bad = scratch("T1 P1\nT1 P2\n");
    auto r = read_tool_file(bad);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, bad + ":2: tool 1 appears twice");
    unlink(bad.c_str());
}

TEST(IoCore, EstopPinsAndPulse)
{
    IoCore io("", false);
    IoPins p;
    std::string err;
    EXPECT_EQ(io.command({"ESTOP_OFF"}, p, err), IoCore::Outcome::Done);
    EXPECT_TRUE(p.user_enable_out);
    EXPECT_TRUE(p.user_request_enable);
    io.end_cycle(p);   // one cycle later
    EXPECT_FALSE(p.user_request_enable);
    EXPECT_TRUE(p.user_enable_out);
    p.coolant_flood = p.lube = p.tool_prepare = true;
    p.tool_prep_number = 4;
    EXPECT_EQ(io.command({"ESTOP_ON"}, p, err), IoCore::Outcome::Done);
    EXPECT_FALSE(p.user_enable_out || p.coolant_flood || p.lube || p.tool_prepare);
    EXPECT_EQ(p.tool_prep_number, 0);
    p.emc_enable_in = false;
    EXPECT_NE(io.status_line(p).find("estop=1"), std::string::npos);
    EXPECT_EQ(io.command({"BOGUS"}, p, err), IoCore::Outcome::Failed);
    EXPECT_EQ(err, "unknown io command 'BOGUS'");
}

TEST(IoCore, NonRandomPrepareAndChange)
{
    std::string path = scratch("T1 P1 Z10\nT5 P3 Z50 ;five\n");
    IoCore io(path, false);
    ASSERT_TRUE(io.load_table());
    IoPins p;
    std::string err;
    ASSERT_EQ(io.command({"TOOL_PREPARE", "5"}, p, err), IoCore::Outcome::Pending);
    EXPECT_TRUE(p.tool_prepare);
    EXPECT_EQ(p.tool_prep_number, 5);
    EXPECT_EQ(p.tool_prep_pocket, 3);
    EXPECT_EQ(p.tool_prep_index, 2);   // line order
    EXPECT_FALSE(io.cycle(p));         // not acknowledged yet
    p.tool_prepared = true;
    EXPECT_TRUE(io.cycle(p));
    EXPECT_FALSE(p.tool_prepare);
    EXPECT_EQ(io.pocket_prepped(), 2);
    ASSERT_EQ(io.command({"TOOL_LOAD"}, p, err), IoCore::Outcome::Pending);
    EXPECT_TRUE(p.tool_change);
    EXPECT_FALSE(io.cycle(p));
    p.tool_changed = true;
    EXPECT_TRUE(io.cycle(p));
    EXPECT_FALSE(p.tool_change);
    EXPECT_EQ(p.tool_number, 5);
    EXPECT_EQ(p.tool_from_pocket, 3);
    EXPECT_EQ(p.tool_prep_number, 0);
    EXPECT_EQ(io.pocket_prepped(), -1);
    // the table is unchanged for a non-random changer
    EXPECT_EQ(io.table_lines(), (std::vector<std::string>{"T1 P1 Z+10.000000", "T5 P3 Z+50.000000 ;five"}));
    // the same tool again: M6 does nothing
    p.tool_prepared = p.tool_changed = false;
    ASSERT_EQ(io.command({"TOOL_PREPARE", "5"}, p, err), IoCore::Outcome::Pending);
    p.tool_prepared = true;
    EXPECT_TRUE(io.cycle(p));
    EXPECT_EQ(io.command({"TOOL_LOAD"}, p, err), IoCore::Outcome::Done);
    // abort cancels a pending prepare
    p.tool_prepared = false;
    ASSERT_EQ(io.command({"TOOL_PREPARE", "1"}, p, err), IoCore::Outcome::Pending);
    io.set_pending_serial(42);
    EXPECT_EQ(io.command({"ABORT"}, p, err), IoCore::Outcome::Done);
    EXPECT_EQ(io.take_cancelled(), 42);
    EXPECT_FALSE(p.tool_prepare);
    unlink(path.c_str());
}

TEST(IoCore, RandomChangerSwapsPockets)
{
    std::string path = scratch("T1 P1 Z10\nT5 P3 Z50\n");
    IoCore io(path, true);
    ASSERT_TRUE(io.load_table());
    IoPins p;
    std::string err;
    ASSERT_EQ(io.command({"TOOL_PREPARE", "5"}, p, err), IoCore::Outcome::Pending);
    EXPECT_EQ(p.tool_prep_pocket, 3);
    EXPECT_EQ(p.tool_prep_index, 3);   // index = pocket
    p.tool_prepared = true;
    EXPECT_TRUE(io.cycle(p));
    ASSERT_EQ(io.command({"TOOL_LOAD"}, p, err), IoCore::Outcome::Pending);
    p.tool_changed = true;
    EXPECT_TRUE(io.cycle(p));
    EXPECT_EQ(p.tool_number, 5);
    EXPECT_EQ(slurp(path), "T5 P0 Z+50.000000\nT1 P1 Z+10.000000\n");   // rewritten, 5 in the spindle
    // tool 1 next: 5 goes back to pocket 1's place
    p.tool_prepared = p.tool_changed = false;
    ASSERT_EQ(io.command({"TOOL_PREPARE", "1"}, p, err), IoCore::Outcome::Pending);
    p.tool_prepared = true;
    EXPECT_TRUE(io.cycle(p));
    ASSERT_EQ(io.command({"TOOL_LOAD"}, p, err), IoCore::Outcome::Pending);
    p.tool_changed = true;
    EXPECT_TRUE(io.cycle(p));
    EXPECT_EQ(slurp(path), "T1 P0 Z+10.000000\nT5 P1 Z+50.000000\n");
    // preparing the tool in the spindle is done at once
    EXPECT_EQ(io.command({"TOOL_PREPARE", "1"}, p, err), IoCore::Outcome::Done);
    unlink(path.c_str());
}

TEST(IoCore, SetOffsetKeepsPocketAndRemark)
{
    std::string path = scratch("T1 P4 Z10 ;keep me\n");
    IoCore io(path, false);
    ASSERT_TRUE(io.load_table());
    IoPins p;
    std::string err;
    std::vector<std::string> w = {"TOOL_SET_OFFSET", "1", "9", "0", "0", "12.5", "0", "0", "0", "0", "0", "0",
                                  "3", "0", "0", "0"};
    ASSERT_EQ(io.command(w, p, err), IoCore::Outcome::Done) << err;
    EXPECT_EQ(slurp(path), "T1 P4 Z+12.500000 D+3.000000 ;keep me\n");
    w[1] = "8";
    ASSERT_EQ(io.command(w, p, err), IoCore::Outcome::Done);   // a new tool is added
    EXPECT_EQ(io.table_lines().size(), 2u);
    w.resize(5);
    EXPECT_EQ(io.command(w, p, err), IoCore::Outcome::Failed);
    EXPECT_EQ(err, "TOOL_SET_OFFSET: bad arguments");
    unlink(path.c_str());
}
