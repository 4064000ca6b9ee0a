// SPDX-License-Identifier: GPL-2.0-or-later
// Cutter radius compensation (gcode.md 11.3): entry, outside corners (arcs around the
// corner), inside corners (intersections), arcs, exit, errors.
#include "interp_test_util.hpp"

using interp_test::expect_error;
using interp_test::Prog;
using V = std::vector<std::string>;

TEST(InterpComp, SquareOutsideLeft)
{
	// a 10x10 square cut CCW with the tool on the left (outside of the square: G42 would
	// be inside); radius 1
	Prog r("G0 X-5 Y-5\nG42.1 D2 F100\nG1 X0 Y0\nG1 X10\nG1 Y10\nG1 X0\nG1 Y0\nG40\nG0 X-5 Y-5\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V want = {
		"STRAIGHT_TRAVERSE(-5.0000, -5.0000, 0.0000)",
		"STRAIGHT_FEED(0.0000, -1.0000, 0.0000)",                     // entry to the offset start of X10
		"STRAIGHT_FEED(10.0000, -1.0000, 0.0000)",
		"ARC_FEED(11.0000, 0.0000, 10.0000, 0.0000, 1, 11.0000, 0.0000, 0.0000)",
		"STRAIGHT_FEED(11.0000, 10.0000, 0.0000)",
		"ARC_FEED(10.0000, 11.0000, 10.0000, 10.0000, 1, 10.0000, 11.0000, 0.0000)",
		"STRAIGHT_FEED(0.0000, 11.0000, 0.0000)",
		"ARC_FEED(-1.0000, 10.0000, 0.0000, 10.0000, 1, -1.0000, 10.0000, 0.0000)",
		"STRAIGHT_FEED(-1.0000, 0.0000, 0.0000)",                     // ends at its offset end
		"STRAIGHT_TRAVERSE(-5.0000, -5.0000, 0.0000)",               // exit, uncompensated
	};
	EXPECT_EQ(r.moves(), want);
}

TEST(InterpComp, InsideCorners)
{
	Prog r("G0 X-5 Y1\nG41.1 D2 F100\nG1 X0 Y0\nG1 X10\nG1 Y10\nG40\nG1 X20 Y20\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V want = {
		"STRAIGHT_TRAVERSE(-5.0000, 1.0000, 0.0000)",
		"STRAIGHT_FEED(0.0000, 1.0000, 0.0000)",
		"STRAIGHT_FEED(9.0000, 1.0000, 0.0000)",     // inside corner: intersection of the offsets
		"STRAIGHT_FEED(9.0000, 10.0000, 0.0000)",
		"STRAIGHT_FEED(20.0000, 20.0000, 0.0000)",
	};
	EXPECT_EQ(r.moves(), want);
}

TEST(InterpComp, ArcsAndToolTableRadius)
{
	rs274::Config c;
	c.tool_table = ::testing::TempDir() + "interp_comp.tbl";
	FILE* f = fopen(c.tool_table.c_str(), "w");
	fputs("T3 P3 D2\n", f);
	fclose(f);
	// a full circle radius 5 around (0,0) cut CCW from (5,0) with the tool outside (G42)
	Prog r("G0 X10 Y-5\nG42 D3 F100\nG1 X5 Y0\nG3 I-5 J0\nG1 X10 Y0\nG40\nG0 X20\nM2\n", c);
	ASSERT_TRUE(r.ok()) << r.error();
	V m = r.moves();
	ASSERT_EQ(m.size(), 5u);
	EXPECT_EQ(m[1], "STRAIGHT_FEED(6.0000, 0.0000, 0.0000)");
	EXPECT_EQ(m[2], "ARC_FEED(5.9161, -1.0000, 0.0000, 0.0000, 1, 5.9161, -1.0000, 0.0000)");   // inside corner
	EXPECT_EQ(m[3], "STRAIGHT_FEED(10.0000, -1.0000, 0.0000)");
	EXPECT_EQ(m[4], "STRAIGHT_TRAVERSE(20.0000, 0.0000, 0.0000)");
	remove(c.tool_table.c_str());
}

TEST(InterpComp, ZMovesWhileOn)
{
	Prog r("G0 X-5 Y-5\nG42.1 D2 F100\nG1 X0 Y0\nG1 X10\nG1 Z-1\nG1 Y10\nG40\nG0 X20\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V want = {
		"STRAIGHT_TRAVERSE(-5.0000, -5.0000, 0.0000)", "STRAIGHT_FEED(0.0000, -1.0000, 0.0000)",
		"STRAIGHT_FEED(10.0000, -1.0000, 0.0000)", "STRAIGHT_FEED(10.0000, -1.0000, -1.0000)",
		"ARC_FEED(11.0000, 0.0000, 10.0000, 0.0000, 1, 11.0000, 0.0000, -1.0000)",
		"STRAIGHT_FEED(11.0000, 10.0000, -1.0000)", "STRAIGHT_TRAVERSE(20.0000, 10.0000, -1.0000)",
	};
	EXPECT_EQ(r.moves(), want);
}

TEST(InterpComp, Errors)
{
	expect_error("G41.1 D1\nG42.1 D1", "Cannot turn cutter radius comp on when on", 2);
	expect_error("G19 G41.1 D1", "Cutter radius compensation allowed only in XY, XZ planes");
	expect_error("G41.1", "D word missing with G41.1 or G42.1");
	expect_error("G41 D9", "Tool 9 not found in the tool table");
	expect_error("G41.1 D4 F10\nG1 X1", "Length of cutter compensation entry move is not greater than the tool radius", 2);
	expect_error("G41.1 D4 F10\nG1 X10\nG3 X12 Y0 R1", "Tool radius not less than arc radius with comp", 3);
	expect_error("G41.1 D1 F10\nG1 X10\nG40\nG2 X12 Y0 R1", "The move just after exiting cutter compensation mode must be straight, not an arc", 4);
	expect_error("G41.1 D1 F10\nG2 X2 Y0 R1", "Cutter compensation entry move must be a straight line (G0 or G1)", 2);
	expect_error("G41.1 D1\nG18", "Cannot change planes with cutter radius compensation on", 2);
	expect_error("G41.1 D1\nG53 G0 X1", "Cannot use g53 with cutter radius comp", 2);
	expect_error("G41.1 D1\nG28", "Cannot use g28 or g30 with cutter radius comp", 2);
	expect_error("G41.1 D1\nG92 X1", "Cannot change axis offsets with cutter radius comp", 2);
	expect_error("G41.1 D1\nG10 L2 P0 X1", "Cannot change axis offsets with cutter radius comp", 2);
	expect_error("G41.1 D1\nG55", "Cannot change coordinate systems with cutter radius compensation on", 2);
	expect_error("G41.1 D1\nG38.2 Z-1 F1", "Cannot probe with cutter radius comp on", 2);
	expect_error("G41.1 D1\nG43", "Cannot change tool offset with cutter radius compensation on", 2);
	expect_error("G41.1 D1\nM48", "Cannot enable overrides with cutter radius compensation on", 2);
	expect_error("G41.1 D1\nM62 P1", "Cannot use M62-M68 with cutter radius compensation on", 2);
	expect_error("G41.1 D1\nG81 X1 Z-1 R1 F1", "Cannot use canned cycles with cutter radius compensation on", 2);
	expect_error("G41.1 D1\nG64", "Cannot change path control mode with cutter radius compensation on", 2);
	expect_error("T0 G41.1 D1\nM6", "Cannot change tools with cutter radius compensation on", 2);
}
