// SPDX-License-Identifier: GPL-2.0-or-later
// M codes (gcode.md 11.1, 12, 13): spindle, coolant, overrides, I/O, stops, tools,
// modal state save/restore, user M codes.
#include <sys/stat.h>

#include <cstdio>

#include "interp_test_util.hpp"

using interp_test::expect_error;
using interp_test::Prog;
using V = std::vector<std::string>;

TEST(InterpMCodes, SpindleAndCoolant)
{
	Prog r("S1200 M3\nM4\nM5\nM19 R90 Q2 P1\nM7\nM8\nM9\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V v = r.calls();
	EXPECT_EQ(V(v.begin(), v.begin() + 10),
	          (V{"SET_SPINDLE_SPEED(0, 1200.0000)", "START_SPINDLE_CLOCKWISE(0)", "START_SPINDLE_COUNTERCLOCKWISE(0)",
	             "STOP_SPINDLE_TURNING(0)", "ORIENT_SPINDLE(0, 90.0000, 1)", "WAIT_SPINDLE_ORIENT_COMPLETE(0, 2.0000)",
	             "MIST_ON()", "FLOOD_ON()", "MIST_OFF()", "FLOOD_OFF()"}));
	rs274::Config c;
	c.orient_offset = 10;
	Prog o("M19 R90\nM2\n", c);
	EXPECT_EQ(o.calls({"ORIENT"}), V{"ORIENT_SPINDLE(0, 100.0000, 0)"});
	expect_error("M19 P3", "P value must be 0,1,or 2 with M19");
	expect_error("M19 R-1", "R value must be within 0..360 with M19");
	expect_error("M19 Q0", "Q word with M19 requires a value > 0");
	expect_error("S-1", "Negative spindle speed used");
}

TEST(InterpMCodes, ConstantSurfaceSpeed)
{
	Prog r("G96 S100 D2000\nG97\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.calls({"SET_SPINDLE_MODE"}),
	          (V{"SET_SPINDLE_MODE(0, 15915.4943, 2000.0000)", "SET_SPINDLE_MODE(0, 0.0000, 0.0000)"}));
	Prog u("G20\nG96 S100\nM2\n");   // ft/min, result in machine mm: 12/(2 pi)*100*25.4
	EXPECT_EQ(u.calls({"SET_SPINDLE_MODE"})[0], "SET_SPINDLE_MODE(0, 4851.0427, UNLIMITED)");
	expect_error("G96 D100", "S word missing with G96");
}

TEST(InterpMCodes, Overrides)
{
	Prog r("M49\nM48\nM50 P0\nM50\nM51 P0\nM52 P1\nM52 P0\nM53 P0\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V v = r.calls();
	EXPECT_EQ(V(v.begin(), v.begin() + 10),
	          (V{"DISABLE_FEED_OVERRIDE()", "DISABLE_SPEED_OVERRIDE(0)", "ENABLE_FEED_OVERRIDE()",
	             "ENABLE_SPEED_OVERRIDE(0)", "DISABLE_FEED_OVERRIDE()", "ENABLE_FEED_OVERRIDE()",
	             "DISABLE_SPEED_OVERRIDE(0)", "ENABLE_ADAPTIVE_FEED()", "DISABLE_ADAPTIVE_FEED()",
	             "DISABLE_FEED_HOLD()"}));
}

TEST(InterpMCodes, InputOutput)
{
	Prog r("M62 P1\nM63 P1\nM64 P2\nM65 P2\nM67 E3 Q2.5\nM68 E0 Q-1\nM66 P4 L3 Q5\n#1=#5399\nM66 E1 L0\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.calls({"SET_", "CLEAR_", "WAIT"}),
	          (V{"SET_MOTION_OUTPUT_BIT(1)", "CLEAR_MOTION_OUTPUT_BIT(1)", "SET_AUX_OUTPUT_BIT(2)",
	             "CLEAR_AUX_OUTPUT_BIT(2)", "SET_MOTION_OUTPUT_VALUE(3, 2.5000)", "SET_AUX_OUTPUT_VALUE(0, -1.0000)",
	             "WAIT(4, DIGITAL, 3, 5.0000)", "WAIT(1, ANALOG, 0, 0.0000)",
	             "SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000)", "SET_XY_ROTATION(0.0000)",
	             "SET_FEED_MODE(0, UNITS_PER_MINUTE)", "SET_FEED_RATE(0.0000)"}));
	EXPECT_EQ(r.param(1), 0);
	expect_error("M66 L0", "Need to have either a valid P or a valid E word with M66");
	expect_error("M66 P1 E1", "Invalid to select both a digital and an analog input with M66");
	expect_error("M66 P1 L2", "Zero timeout with wait type != immediate return");
	expect_error("M66 E1 L1 Q1", "Can't select analog input with wait type != immediate return");
	expect_error("M66 P1 L5 Q1", "Unknown wait type 5 with M66");
	expect_error("M64", "No valid P word with M64");
	expect_error("M68 E1", "No valid Q word with M68");
}

TEST(InterpMCodes, Stops)
{
	Prog r("M0\nM1\nM60\nM30\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.calls({"PROGRAM", "OPTIONAL", "PALLET"}),
	          (V{"PROGRAM_STOP()", "OPTIONAL_PROGRAM_STOP()", "PALLET_SHUTTLE()", "PROGRAM_STOP()",
	             "PALLET_SHUTTLE()", "PROGRAM_END()"}));
}

TEST(InterpMCodes, Tools)
{
	rs274::Config c;
	c.tool_table = ::testing::TempDir() + "interp_m.tbl";
	FILE* f = fopen(c.tool_table.c_str(), "w");
	fputs("T5 P3 Z1\n", f);
	fclose(f);
	c.tool_change_quill_up = true;
	Prog r("G0 Z-5\nT5 M6\n#1=#<_current_tool> #2=#<_current_pocket> #3=#<_selected_tool>\nM61 Q0\n#4=#5400\nT0\nM2\n", c);
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.calls({"SELECT", "CHANGE", "STRAIGHT", "STOP_SPINDLE"}),
	          (V{"STRAIGHT_TRAVERSE(0.0000, 0.0000, -5.0000)", "SELECT_TOOL(5)", "STOP_SPINDLE_TURNING(0)",
	             "STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000)", "CHANGE_TOOL(5)", "CHANGE_TOOL_NUMBER(0)",
	             "SELECT_TOOL(0)", "SELECT_PLANE(CANON_PLANE_XY)", "STOP_SPINDLE_TURNING(0)"}));
	EXPECT_EQ(r.param(1), 5);
	EXPECT_EQ(r.param(2), 3);
	EXPECT_EQ(r.param(3), 5);
	EXPECT_EQ(r.param(4), 0);
	expect_error("M6", "Need tool prepared -Txx- for toolchange", 1, c);
	expect_error("T7", "Requested tool 7 not found in the tool table", 1, c);
	expect_error("T-1", "Negative tool id (tool not found)", 1, c);
	expect_error("M61 Q-1", "Need non-negative Q-word to specify tool number with M61", 1, c);
	expect_error("M61 Q9", "Requested tool 9 not found in the tool table", 1, c);
	remove(c.tool_table.c_str());
}

TEST(InterpMCodes, ModalStateSaveRestore)
{
	Prog r("G21 G90 F100 M70\nG20 G91 F5 M3 S200 M8\nM72\n#1=#<_metric> #2=#<_absolute> #3=#<_feed> #4=#<_spindle_on>\n"
	      "o<s> sub\nM73\nG20 G91 F7\no<s> endsub\no<s> call\n#5=#<_metric> #6=#<_feed>\nM71\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.param(1), 1);
	EXPECT_EQ(r.param(2), 1);
	EXPECT_EQ(r.param(3), 100);
	EXPECT_EQ(r.param(4), 0);
	EXPECT_EQ(r.param(5), 1);
	EXPECT_EQ(r.param(6), 100);
	expect_error("M72", "Cannot restore modal state: nothing saved by M70 or M73 at this call level");
	expect_error("M70\nM71\nM72", "Cannot restore modal state: nothing saved by M70 or M73 at this call level", 3);
}

TEST(InterpMCodes, UserMCodes)
{
	std::string dir = ::testing::TempDir();
	std::string prog = dir + "/M123";
	FILE* f = fopen(prog.c_str(), "w");
	fputs("#!/bin/sh\nexit 0\n", f);
	fclose(f);
	chmod(prog.c_str(), 0755);
	rs274::Config c;
	c.user_m_path = {dir + "/nonexistent", dir};
	Prog r("M123 P1.5 Q-2\nM2\n", c);
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.calls({"USER_M_CODE"}), V{"USER_M_CODE(123, \"" + dir + "/" + "M123\", 1.5000, -2.0000)"});
	expect_error("M124", "Unknown m code used: M124", 1, c);
	remove(prog.c_str());
}
