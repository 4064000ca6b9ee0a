// SPDX-License-Identifier: GPL-2.0-or-later
// Cutter radius compensation (gcode.md 11.3): entry lines and arcs, exit, every corner
// type (line/line, line/arc, arc/line, arc/arc; inside = intersection of the offset
// paths, outside = arc of the tool radius around the corner point), plunges and other
// calls between two compensated moves, G18, the radius sources, errors.
// Expected values are worked out by hand in the comments (r = tool radius).
#include "interp_test_util.hpp"

using interp_test::expect_error;
using interp_test::Prog;
using V = std::vector<std::string>;

TEST(InterpComp, SquareOutsideRight)
{
	// 10x10 square cut CCW, tool on the right (outside), r = 1. Entry from (-5,-5) to
	// (0,0): d = sqrt(50), the tool path turns right by asin(1/d), direction (0.8, 0.6),
	// and is cut at the intersection with the offset of X10 (y = -1): (0.3333, -1).
	Prog r("G0 X-5 Y-5\nG42.1 D2 F100\nG1 X0 Y0\nG1 X10\nG1 Y10\nG1 X0\nG1 Y0\nG40\nG0 X-5 Y-5\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V want = {
		"STRAIGHT_TRAVERSE(-5.0000, -5.0000, 0.0000)",
		"STRAIGHT_FEED(0.3333, -1.0000, 0.0000)",
		"STRAIGHT_FEED(10.0000, -1.0000, 0.0000)",
		"ARC_FEED(11.0000, 0.0000, 10.0000, 0.0000, 1, 11.0000, 0.0000, 0.0000)",
		"STRAIGHT_FEED(11.0000, 10.0000, 0.0000)",
		"ARC_FEED(10.0000, 11.0000, 10.0000, 10.0000, 1, 10.0000, 11.0000, 0.0000)",
		"STRAIGHT_FEED(0.0000, 11.0000, 0.0000)",
		"ARC_FEED(-1.0000, 10.0000, 0.0000, 10.0000, 1, -1.0000, 10.0000, 0.0000)",
		"STRAIGHT_FEED(-1.0000, 0.0000, 0.0000)",                     // exit: its offset end
		"STRAIGHT_TRAVERSE(-5.0000, -5.0000, 0.0000)",               // then uncompensated
	};
	EXPECT_EQ(r.moves(), want);
}

TEST(InterpComp, LineLineInsideAndEntryOutside)
{
	// left, r = 1. Entry (-10,0) -> (0,0): direction turned left by asin(0.1), ends at
	// the tangent point (-0.1, 0.995); the corner to X10 turns right = outside: arc
	// around (0,0) to (0,1). X10 -> Y10 turns left = inside: offsets y = 1 and x = 9
	// meet at (9,1).
	Prog r("G0 X-10 Y0\nG41.1 D2 F100\nG1 X0\nG1 X10\nG1 Y10\nG40\nG1 X20 Y20\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V want = {
		"STRAIGHT_TRAVERSE(-10.0000, 0.0000, 0.0000)",
		"STRAIGHT_FEED(-0.1000, 0.9950, 0.0000)",
		"ARC_FEED(0.0000, 1.0000, 0.0000, 0.0000, -1, 0.0000, 1.0000, 0.0000)",
		"STRAIGHT_FEED(9.0000, 1.0000, 0.0000)",
		"STRAIGHT_FEED(9.0000, 10.0000, 0.0000)",
		"STRAIGHT_FEED(20.0000, 20.0000, 0.0000)",
	};
	EXPECT_EQ(r.moves(), want);
}

TEST(InterpComp, LineArcArcLineCorners)
{
	// left, r = 1 (same entry as above).
	// X10 -> G2 centre (15,0): the arc starts upwards, a left turn = inside; the tool is
	//   outside the arc (offset radius 6): y = 1 meets it at x = 15 - sqrt(35) = 9.0839.
	// G2 -> G3 centre (25,0): tangent at (20,0), both offsets end/start at (21,0).
	// G3 ends at (30,0) going up, G1 Y-10 goes down: a reversal = outside, half circle
	//   around (30,0) from (29,0) to (31,0), clockwise.
	// Y-10 -> X0 turns right = outside: arc around (30,-10) to (30,-11).
	// The M3, the plunge and the comment wait behind the held Y-10 move; the plunge
	// runs at its final end point.
	Prog r("G0 X-10 Y0\nG41.1 D2 F100\nG1 X0 Y0\nG1 X10\nG2 X20 Y0 R5\nG3 X30 Y0 R5\nG1 Y-10\n"
	       "M3 S100\nG1 Z-1\n(a comment)\nG1 X0\nG40\nG1 X-5 Y-20\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V want = {
		"STRAIGHT_TRAVERSE(-10.0000, 0.0000, 0.0000)",
		"STRAIGHT_FEED(-0.1000, 0.9950, 0.0000)",
		"ARC_FEED(0.0000, 1.0000, 0.0000, 0.0000, -1, 0.0000, 1.0000, 0.0000)",
		"STRAIGHT_FEED(9.0839, 1.0000, 0.0000)",
		"ARC_FEED(21.0000, 0.0000, 15.0000, 0.0000, -1, 21.0000, 0.0000, 0.0000)",
		"ARC_FEED(29.0000, 0.0000, 25.0000, 0.0000, 1, 29.0000, 0.0000, 0.0000)",
		"ARC_FEED(31.0000, 0.0000, 30.0000, 0.0000, -1, 31.0000, 0.0000, 0.0000)",
		"STRAIGHT_FEED(31.0000, -10.0000, 0.0000)",
		"SET_SPINDLE_SPEED(0, 100.0000)",
		"START_SPINDLE_CLOCKWISE(0)",
		"STRAIGHT_FEED(31.0000, -10.0000, -1.0000)",
		"COMMENT(\"a comment\")",
		"ARC_FEED(30.0000, -11.0000, 30.0000, -10.0000, -1, 30.0000, -11.0000, -1.0000)",
		"STRAIGHT_FEED(0.0000, -11.0000, -1.0000)",
		"STRAIGHT_FEED(-5.0000, -20.0000, -1.0000)",
	};
	EXPECT_EQ(r.calls({"STRAIGHT", "ARC", "SET_SPINDLE", "START_SPINDLE", "COMMENT"}), want);
}

TEST(InterpComp, ArcToArcInsideAndOutside)
{
	// right, r = 2. Entry (0,0) -> (10,0) turned right by asin(0.2): (9.6, -1.9596).
	// -> G2 centre (15,0) starting upwards: left turn = outside for the right side: arc
	//   around (10,0) to (12,0). The tool is inside this arc (offset radius 3).
	// G2 ends at (20,0) going down, the next G2 (centre (25,0)) starts going up: a cusp,
	//   outside: arc around (20,0) from (18,0) to (22,0) counter-clockwise.
	Prog r("G42.1 D4 F10\nG1 X10\nG2 X20 Y0 R5\nG2 X30 Y0 R5\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V want = {
		"STRAIGHT_FEED(9.6000, -1.9596, 0.0000)",
		"ARC_FEED(12.0000, 0.0000, 10.0000, 0.0000, 1, 12.0000, 0.0000, 0.0000)",
		"ARC_FEED(18.0000, 0.0000, 15.0000, 0.0000, -1, 18.0000, 0.0000, 0.0000)",
		"ARC_FEED(22.0000, 0.0000, 20.0000, 0.0000, 1, 22.0000, 0.0000, 0.0000)",
		"ARC_FEED(28.0000, 0.0000, 25.0000, 0.0000, -1, 28.0000, 0.0000, 0.0000)",
	};
	EXPECT_EQ(r.moves(), want);
	// inside arc/arc: left, r = 1. G3 centre (0,10) from (0,0) to (10,10) (the tool is
	// inside it, offset radius 9), then G2 centre (20,10) (tool outside, radius 11)
	// turning... the arcs meet at (10,10) with a left turn: intersection of the circles
	// (0,10) r 9 and (20,10) r 11: x = (400 + 81 - 121) / 40 = 9, y = 10.
	Prog a("G0 X-10 Y0\nG41.1 D2 F10\nG1 X0\nG3 X10 Y10 I0 J10\nG2 X20 Y0 I10 J0\nG40\nG1 X30 Y-10\nM2\n");
	ASSERT_TRUE(a.ok()) << a.error();
	V m = a.moves();
	ASSERT_EQ(m.size(), 6u);
	EXPECT_EQ(m[3], "ARC_FEED(9.0000, 10.0000, 0.0000, 10.0000, 1, 9.0000, 10.0000, 0.0000)");
	EXPECT_EQ(m[4], "ARC_FEED(20.0000, -1.0000, 20.0000, 10.0000, -1, 20.0000, -1.0000, 0.0000)");
}

TEST(InterpComp, EntryArcAndToolTableRadius)
{
	rs274::Config c;
	c.tool_table = ::testing::TempDir() + "interp_comp.tbl";
	FILE* f = fopen(c.tool_table.c_str(), "w");
	fputs("T3 P3 D2\n", f);
	fclose(f);
	// G42 D3: r = 1. Entry arc G3 centre (0,0) from (0,-10) to (10,0): the tool is
	// outside (radius 11); its end moves to (11,0), the centre stays (canon spirals).
	// -> X20 turns right = inside: y = -1 meets the circle radius 11 at x = sqrt(120).
	Prog r("G0 X0 Y-10\nG42 D3 F100\nG3 X10 Y0 I0 J10\nG1 X20\nG40\nG0 X30\nM2\n", c);
	ASSERT_TRUE(r.ok()) << r.error();
	V want = {
		"STRAIGHT_TRAVERSE(0.0000, -10.0000, 0.0000)",
		"ARC_FEED(10.9545, -1.0000, 0.0000, 0.0000, 1, 10.9545, -1.0000, 0.0000)",
		"STRAIGHT_FEED(20.0000, -1.0000, 0.0000)",
		"STRAIGHT_TRAVERSE(30.0000, 0.0000, 0.0000)",
	};
	EXPECT_EQ(r.moves(), want);
	// no D: the tool in the spindle (T3 M6)
	Prog s("T3 M6\nG0 X0 Y-10\nG42 F100\nG3 X10 Y0 I0 J10\nG1 X20\nG40\nG0 X30\nM2\n", c);
	ASSERT_TRUE(s.ok()) << s.error();
	EXPECT_EQ(s.moves()[1], want[1]);
	remove(c.tool_table.c_str());
}

TEST(InterpComp, PlungeKeepsInsideCorner)
{
	// left, r = 1: X10 then (plunge) Y10 is an inside corner at (9,1) whatever happens
	// in Z between the two; the plunge runs at (9,1).
	Prog r("G0 X-10\nG41.1 D2 F100\nG1 X0\nG1 X10\nG0 Z-1\nG1 Z-2\nG1 Y10\nG40\nG0 X20\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V want = {
		"STRAIGHT_TRAVERSE(-10.0000, 0.0000, 0.0000)",
		"STRAIGHT_FEED(-0.1000, 0.9950, 0.0000)",
		"ARC_FEED(0.0000, 1.0000, 0.0000, 0.0000, -1, 0.0000, 1.0000, 0.0000)",
		"STRAIGHT_FEED(9.0000, 1.0000, 0.0000)",
		"STRAIGHT_TRAVERSE(9.0000, 1.0000, -1.0000)",
		"STRAIGHT_FEED(9.0000, 1.0000, -2.0000)",
		"STRAIGHT_FEED(9.0000, 10.0000, -2.0000)",
		"STRAIGHT_TRAVERSE(20.0000, 10.0000, -2.0000)",
	};
	EXPECT_EQ(r.moves(), want);
}

TEST(InterpComp, HelixAndXZPlane)
{
	// a move in the plane with Z: the plane part is compensated, Z follows
	Prog h("G0 X-10\nG41.1 D2 F100\nG1 X0 Z-1\nG1 X10 Z-2\nG40\nG1 X20\nM2\n");
	ASSERT_TRUE(h.ok()) << h.error();
	V m = h.moves();
	ASSERT_EQ(m.size(), 5u);
	EXPECT_EQ(m[1], "STRAIGHT_FEED(-0.1000, 0.9950, -1.0000)");
	EXPECT_EQ(m[2], "ARC_FEED(0.0000, 1.0000, 0.0000, 0.0000, -1, 0.0000, 1.0000, -1.0000)");
	EXPECT_EQ(m[3], "STRAIGHT_FEED(10.0000, 1.0000, -2.0000)");
	EXPECT_EQ(m[4], "STRAIGHT_FEED(20.0000, 0.0000, -2.0000)");
	// G18: plane coordinates (Z, X). Left, r = 1: entry (0,0) -> Z10 turned left by
	// asin(0.1); -> X10 turns left = inside: the offset of X10 is Z = 9, met at X 0.9045.
	Prog r("G18 G0 X0 Z0\nG41.1 D2 F100\nG1 Z10\nG1 X10\nG40\nG1 X20 Z20\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V want = {
		"STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000)",
		"STRAIGHT_FEED(0.9045, 0.0000, 9.0000)",
		"STRAIGHT_FEED(10.0000, 0.0000, 9.0000)",
		"STRAIGHT_FEED(20.0000, 0.0000, 20.0000)",
	};
	EXPECT_EQ(r.moves(), want);
}

TEST(InterpComp, CallsWaitBehindTheHeldMove)
{
	// the F of the next move and a dwell reach canon after the held move; the arc
	// around the corner belongs to the next move (its feed, after the calls)
	Prog r("G41.1 D2 F100\nG1 X10\nG4 P1\nG1 X20 F50\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V want = {
		"SET_FEED_RATE(100.0000)", "STRAIGHT_FEED(9.9000, 0.9950, 0.0000)",
		"DWELL(1.0000)", "SET_FEED_RATE(50.0000)",
		"ARC_FEED(10.0000, 1.0000, 10.0000, 0.0000, -1, 10.0000, 1.0000, 0.0000)",
		"STRAIGHT_FEED(20.0000, 1.0000, 0.0000)",
	};
	V got = r.calls({"SET_FEED_RATE", "STRAIGHT", "ARC", "DWELL"});
	got.pop_back();   // M2's feed rate 0
	EXPECT_EQ(got, want);
}

TEST(InterpComp, Errors)
{
	expect_error("G41.1 D1\nG42.1 D1", "Cannot turn cutter radius comp on when on", 2);
	expect_error("G19 G41.1 D1", "Cutter radius compensation allowed only in XY, XZ planes");
	expect_error("G41.1", "D word missing with G41.1 or G42.1");
	expect_error("G41 D9", "Tool 9 not found in the tool table");
	expect_error("G41.1 D4 F10\nG1 X1", "Length of cutter compensation entry move is not greater than the tool radius", 2);
	expect_error("G41.1 D4 F10\nG2 X1 Y1 I0 J1", "Radius of cutter compensation entry arc is not greater than the tool radius", 2);
	// concave arcs the tool does not fit in (left of a CCW arc = inside)
	expect_error("G41.1 D4 F10\nG1 X10\nG3 X12 Y0 R1", "Tool radius not less than arc radius with comp", 3);
	expect_error("G41.1 D2 F10\nG1 X10\nG3 X10 Y2 I0 J1", "Tool radius not less than arc radius with comp", 3);
	// inside corners the offset paths cannot meet in
	expect_error("G41.1 D2 F10\nG1 X10\nG1 X0 Y0.01", "Zero degree inside corner is invalid for cutter compensation", 3);
	expect_error("G41.1 D2 F10\nG1 X10\nG3 X12 Y2 I0 J2\nG1 X12 Y-10",
	             "Arc to straight motion makes a corner the compensated tool can't fit in without gouging", 4);
	// line y = 0 (offset y = 2), then a CCW arc centre (7.042, 0.5) radius 3 turning
	// left: the tool runs inside it on radius 1, a circle that never reaches y = 2
	expect_error("G41.1 D4 F10\nG1 X5\nG1 X10 Y0\nG3 X7.5417 Y3.4580 I-2.9580 J0.5",
	             "Arc move in concave corner cannot be reached by the tool without gouging", 4);
	expect_error("G42.1 D4 F10\nG1 X10\nG1 X0 Y-2", "Inside corner too tight: the compensated tool would gouge the previous move", 3);
	expect_error("G41.1 D1 F10\nG1 X10\nG40\nG2 X12 Y0 R1", "The move just after exiting cutter compensation mode must be straight, not an arc", 4);
	expect_error("G41.1 D4 F10\nG1 X10\nG40\nG1 X9.5", "Length of cutter compensation exit move is not greater than the tool radius", 4);
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
	// bounded memory: calls queued behind a held move
	expect_error("G41.1 D1 F10\nG1 X10\no1 repeat [20000]\nG4 P0\no1 endrepeat",
	             "More than 10000 calls between two moves with cutter radius compensation on", 4);
}
