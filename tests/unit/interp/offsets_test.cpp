// SPDX-License-Identifier: GPL-2.0-or-later
// Coordinate systems and offsets (gcode.md 7) and tool length offsets (gcode.md 11.2).
#include <cstdio>

#include "interp_test_util.hpp"

using interp_test::expect_error;
using interp_test::Prog;
using V = std::vector<std::string>;

// Each test gets its own table file: ctest runs the tests of this file as parallel processes,
// and one test's remove() must not pull the table from under another.
static rs274::Config with_tools()
{
	rs274::Config c;
	c.tool_table = ::testing::TempDir() + "interp_offsets." +
	               ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".tbl";
	FILE* f = fopen(c.tool_table.c_str(), "w");
	fputs("T1 P1 Z10 D6\nT2 P2 X1 Z5 D2 ; remark\n", f);
	fclose(f);
	return c;
}

TEST(InterpOffsets, WorkSystemsG53G92)
{
	Prog r("G10 L2 P1 X10 Y20 Z0\nG10 L2 P2 X-5\nG54 G0 X1 Y1\nG55 G0 X1 Y1\nG53 G0 X0 Y0\n"
	      "G92 X2\n#1=#5211 #2=#5210\nG0 X0\nG92.1\nG0 X0\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.moves(), (V{"STRAIGHT_TRAVERSE(11.0000, 21.0000, 0.0000)", "STRAIGHT_TRAVERSE(-4.0000, 1.0000, 0.0000)",
	                        "STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000)", "STRAIGHT_TRAVERSE(-2.0000, 0.0000, 0.0000)",
	                        "STRAIGHT_TRAVERSE(-5.0000, 0.0000, 0.0000)"}));
	EXPECT_EQ(r.param(1), 3);
	EXPECT_EQ(r.param(2), 1);
	EXPECT_EQ(r.param(5211), 0);
	EXPECT_EQ(r.param(5220), 1);   // M2 selected G54 again
}

TEST(InterpOffsets, G92FamilyAndG52)
{
	Prog r("G52 X5\nG0 X0\nG92.2\nG0 X0\n#1=#5211 #2=#5210\nG92.3\nG0 X1\nG92.1\nG0 X1\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.moves(), (V{"STRAIGHT_TRAVERSE(5.0000, 0.0000, 0.0000)", "STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000)",
	                        "STRAIGHT_TRAVERSE(6.0000, 0.0000, 0.0000)", "STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000)"}));
	EXPECT_EQ(r.param(1), 5);
	EXPECT_EQ(r.param(2), 0);
}

TEST(InterpOffsets, G10L20AndRotation)
{
	Prog r("G0 X3 Y4\nG10 L20 P1 X0 Y0\n#1=#5221 #2=#5222\nG0 X1\nG10 L2 P1 X0 Y0 R90\nG0 X1 Y0\n"
	      "G10 L20 P0 X0 Y0\nG0 X0 Y1\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.param(1), 3);
	EXPECT_EQ(r.param(2), 4);
	auto m = r.moves();
	ASSERT_EQ(m.size(), 4u);
	EXPECT_EQ(m[1], "STRAIGHT_TRAVERSE(4.0000, 4.0000, 0.0000)");
	EXPECT_EQ(m[2], "STRAIGHT_TRAVERSE(0.0000, 1.0000, 0.0000)");
	EXPECT_EQ(m[3], "STRAIGHT_TRAVERSE(-1.0000, 1.0000, 0.0000)");   // +Y of the rotated system is -X
	expect_error("G10 L2 P10 X1", "P value out of range (0-9) with G10 L2");
	expect_error("G10 L20 P-1 X1", "P value out of range (0-9) with G10 L20");
	expect_error("G10 L2 P1.5 X1", "P value not an integer with G10");
	expect_error("G10 L2 P1 J1", "I J words not allowed with G10 L2");
	expect_error("G10 L20 P1 X0 R10", "R not allowed in G10 L20");
	expect_error("G10 L3 P1 X1", "Line with G10 does not have L0, L1, L10, L11, L2, or L20");
	expect_error("G10 L2 X1", "P word missing with G10 L2");
}

TEST(InterpOffsets, G28G30)
{
	Prog r("G0 X5 Y6 Z7\nG28.1\nG0 X1 Y2 Z3\nG30.1\nG0 X0 Y0 Z0\nG28 Z2\nG28\nG30 G91 X1\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	auto m = r.moves();
	V want = {"STRAIGHT_TRAVERSE(0.0000, 0.0000, 2.0000)", "STRAIGHT_TRAVERSE(0.0000, 0.0000, 7.0000)",
	          "STRAIGHT_TRAVERSE(0.0000, 0.0000, 7.0000)", "STRAIGHT_TRAVERSE(5.0000, 6.0000, 7.0000)",
	          "STRAIGHT_TRAVERSE(6.0000, 6.0000, 7.0000)", "STRAIGHT_TRAVERSE(1.0000, 6.0000, 7.0000)"};
	EXPECT_EQ(V(m.end() - 6, m.end()), want);
	EXPECT_EQ(r.param(5161), 5);
	EXPECT_EQ(r.param(5183), 3);
}

TEST(InterpOffsets, ToolLength)
{
	rs274::Config c = with_tools();
	Prog r("T1 M6\n#1=#5400 #2=#5403 #3=#5410\nG43\n#4=#5083\nG0 Z0\nG43.1 Z2.5\nG0 Z0\nG43 H1\n"
	      "G43.2 Z0.5\nG0 Z0\nG43.2 H2\nG0 X0 Z0\nG49\nG0 X0 Z0\nG53 G0 Z0\nM2\n", c);
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.param(1), 1);
	EXPECT_EQ(r.param(2), 10);
	EXPECT_EQ(r.param(3), 6);
	EXPECT_EQ(r.param(4), 10);
	EXPECT_EQ(r.moves(), (V{"STRAIGHT_TRAVERSE(0.0000, 0.0000, 10.0000)", "STRAIGHT_TRAVERSE(0.0000, 0.0000, 2.5000)",
	                        "STRAIGHT_TRAVERSE(0.0000, 0.0000, 10.5000)", "STRAIGHT_TRAVERSE(1.0000, 0.0000, 15.5000)",
	                        "STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000)", "STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000)"}));
	expect_error("G43 H9", "Tool 9 not found in the tool table", 1, c);
	expect_error("G43.2 H1 Z1", "Cannot use both H word and axis words with G43.2", 1, c);
	expect_error("G43.2", "G43.2 needs an H word or axis words", 1, c);
	expect_error("G43 H-1", "Negative h word used", 1, c);
	remove(c.tool_table.c_str());
}

TEST(InterpOffsets, ToolTableEntries)
{
	rs274::Config c = with_tools();
	Prog r("G10 L1 P2 Z3 R1.5 I10 J20 Q3\nG0 X0 Y0 Z0\nG10 L10 P1 Z1\nG10 L11 P1 Z2\nG10 L0\nM2\n", c);
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.calls({"SET_TOOL_TABLE_ENTRY", "RELOAD"}),
	          (V{"SET_TOOL_TABLE_ENTRY(2, 2, 1.0000, 0.0000, 3.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 3.0000, 10.0000, 20.0000, 3)",
	             "SET_TOOL_TABLE_ENTRY(1, 1, 0.0000, 0.0000, -1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 6.0000, 0.0000, 0.0000, 0)",
	             "SET_TOOL_TABLE_ENTRY(1, 1, 0.0000, 0.0000, -2.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 6.0000, 0.0000, 0.0000, 0)",
	             "RELOAD_TOOL_TABLE()"}));
	expect_error("G10 L1 P0 Z1", "P value out of range with G10 L1", 1, c);
	expect_error("G10 L1 P5 Z1", "Tool 5 not found in the tool table (G10 L1)", 1, c);
	remove(c.tool_table.c_str());
}

TEST(InterpOffsets, ToolTableFileErrors)
{
	rs274::Config c;
	c.tool_table = ::testing::TempDir() + "interp_bad.tbl";
	FILE* f = fopen(c.tool_table.c_str(), "w");
	fputs("T1 P1 Z1\nT2 P2 K7\n", f);
	fclose(f);
	std::ostringstream out;
	rs274::PrintCanon canon(out, c.axes);
	rs274::Interp in(canon, c);
	EXPECT_FALSE(in.init());
	EXPECT_EQ(in.error().message, c.tool_table + ":2: unknown tool table field 'K7'");
	remove(c.tool_table.c_str());
}

TEST(InterpOffsets, ParameterFileRoundTrip)
{
	rs274::Config c;
	c.parameter_file = ::testing::TempDir() + "interp_rt.var";
	remove(c.parameter_file.c_str());
	{
		Prog r("G10 L2 P3 X1.5 Y-2 R45\n#5161=7\nG92 X-1\n#100=1\nM2\n", c);
		ASSERT_TRUE(r.ok()) << r.error();
		ASSERT_TRUE(r.interp.save_parameters());
	}
	Prog again("#1=#5261 #2=#5262 #3=#5270 #4=#5161 #5=#5211 #6=#5210 #7=#100\nM2\n", c);
	ASSERT_TRUE(again.ok()) << again.error();
	EXPECT_EQ(again.param(1), 1.5);
	EXPECT_EQ(again.param(2), -2);
	EXPECT_EQ(again.param(3), 45);
	EXPECT_EQ(again.param(4), 7);
	EXPECT_EQ(again.param(5), 1);
	EXPECT_EQ(again.param(6), 1);
	EXPECT_EQ(again.param(7), 0);   // #100 was neither in the file nor persistent
	remove(c.parameter_file.c_str());
	remove((c.parameter_file + ".bak").c_str());
}
