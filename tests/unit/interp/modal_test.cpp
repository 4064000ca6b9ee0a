// SPDX-License-Identifier: GPL-2.0-or-later
// Modal groups (gcode.md 2) and the order of execution inside one block (gcode.md 3).
#include "interp_test_util.hpp"

using interp_test::expect_error;
using interp_test::mill;
using interp_test::Prog;

// Two codes of every G group, and of every M group, on one line.
TEST(InterpModal, SameGroupTwiceIsAnError)
{
	const char* g_pairs[] = {
		"G4 G10 L2 P1 X1",        // 0
		"G0 G1 X1",               // 1 motion
		"G17 G18",                // 2 plane
		"G90 G91",                // 3 distance
		"G90.1 G91.1",            // 4 arc distance
		"G93 G94",                // 5 feed mode
		"G20 G21",                // 6 units
		"G40 G41",                // 7 cutter comp
		"G43 G49",                // 8 tool length
		"G98 G99",                // 10 return mode
		"G54 G55",                // 12 coordinate system
		"G61 G64",                // 13 path control
		"G96 G97 S1",             // 14 spindle mode
		"G7 G8",                  // 15 lathe diameter
		"G92.1 G92.2",            // 16 G92 applied
	};
	for (const char* p : g_pairs)
		expect_error(p, "Two g codes used from same modal group");
	const char* m_pairs[] = {"M0 M1", "M62 P1 M63 P1", "M6 M61 Q1", "M3 M5", "M3 M73",
	                         "M7 M9", "M48 M49", "M100 M101"};
	for (const char* p : m_pairs)
		expect_error(p, "Two m codes used from same modal group");
}

TEST(InterpModal, DifferentGroupsShareALine)
{
	Prog r("G17 G21 G40 G49 G54 G80 G90 G94 G98 G64 G91.1 G97 G8\nM7 M8\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.calls({"MIST_ON", "FLOOD_ON"}), (std::vector<std::string>{"FLOOD_ON()", "MIST_ON()"}));
}

TEST(InterpModal, UnknownAndOutOfRangeCodes)
{
	expect_error("G100", "G-code out of range");
	expect_error("G-1", "Negative g code used");
	expect_error("G12", "Unknown g code used");
	expect_error("G5.4 X1", "Unknown g code used");
	expect_error("M20", "Unknown m code used: M20");
	expect_error("M200", "M-code greater than 199: M200");
	expect_error("M-1", "Negative m code used");
	expect_error("M97 P1", "Unknown m code used: M97");
}

// gcode.md 3: comment, G96, G93-95, F, S, T, M I/O, M6, spindle, coolant, overrides,
// user M, G4, plane, units, comp, TLO, coordinate system, path control, distance,
// return mode, group 0, motion, stop.
TEST(InterpModal, PerBlockOrder)
{
	rs274::Config c;
	Prog r("M0 G1 X1 G64 G55 G4 P0.5 M8 M3 M67 E2 Q1 S1000 F50 G95 (MSG,first)\nM2\n", c);
	ASSERT_TRUE(r.ok()) << r.error();
	auto v = r.calls();
	std::vector<std::string> want = {
		"MESSAGE(\"first\")",
		"SET_FEED_MODE(0, UNITS_PER_REVOLUTION)",
		"SET_FEED_RATE(50.0000)",
		"SET_SPINDLE_SPEED(0, 1000.0000)",
		"SET_MOTION_OUTPUT_VALUE(2, 1.0000)",
		"START_SPINDLE_CLOCKWISE(0)",
		"FLOOD_ON()",
		"DWELL(0.5000)",
		"SET_G5X_OFFSET(2, 0.0000, 0.0000, 0.0000)",
		"SET_XY_ROTATION(0.0000)",
		"SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, 0.5000)",   // G64 shares P with G4
		"SET_NAIVECAM_TOLERANCE(1.0000)",                       // ... and Q with M67
		"STRAIGHT_FEED(1.0000, 0.0000, 0.0000)",
		"PROGRAM_STOP()",
	};
	ASSERT_GE(v.size(), want.size());
	EXPECT_EQ(std::vector<std::string>(v.begin(), v.begin() + want.size()), want);
}

TEST(InterpModal, ToolPrepareBeforeChangeBeforeTloBeforeMotion)
{
	rs274::Config c;
	c.tool_table = ::testing::TempDir() + "interp_order.tbl";
	FILE* f = fopen(c.tool_table.c_str(), "w");
	fputs("T4 P4 Z2\n", f);
	fclose(f);
	Prog r("G43 G0 Z0 M6 T4\nM2\n", c);
	ASSERT_TRUE(r.ok()) << r.error();
	auto v = r.calls();
	std::vector<std::string> want = {"SELECT_TOOL(4)", "STOP_SPINDLE_TURNING(0)", "CHANGE_TOOL(4)",
	                                 "USE_TOOL_LENGTH_OFFSET(0.0000, 0.0000, 2.0000)",
	                                 "STRAIGHT_TRAVERSE(0.0000, 0.0000, 2.0000)"};
	EXPECT_EQ(std::vector<std::string>(v.begin(), v.begin() + 5), want);
	remove(c.tool_table.c_str());
}

TEST(InterpModal, AxisWordUsers)
{
	expect_error("G1 G92 X0", "Cannot use two g codes that both use axis values");
	expect_error("G0 G10 L2 P1 X1", "Cannot use two g codes that both use axis values");
	expect_error("G0 G43.1 Z1", "Cannot use two g codes that both use axis values");
	expect_error("G80 X1", "Cannot use axis values with g80");
	expect_error("G80\nX1", "Cannot use axis values without a g code that uses them", 2);
	expect_error("G38.2 F10", "All axes missing with motion code");
	expect_error("G92", "All axes missing with g52 or g92");
	expect_error("G52", "All axes missing with g52 or g92");
	// the active motion mode takes bare axis words
	Prog r("G1 F10 X1\nY2\nM2\n");
	EXPECT_EQ(r.moves().size(), 2u);
}

TEST(InterpModal, UnusedWords)
{
	expect_error("D1", "D word with no G41, G41.1, G42, G42.1, G71, G71.1, G71.2 or G96 to use it");
	expect_error("G0 X1 H1", "H word with no G43 or G76 to use it");
	expect_error("G0 X1 I1", "I word with no G2, G3, G5, G5.1, G10, G33.1, G76, or G87 to use it");
	expect_error("J1", "J word with no G2, G3, G5, G5.1, G10, G76 or G87 to use it");
	expect_error("K1", "K word with no G2, G3, G33, G33.1, G76, or G87 to use it");
	expect_error("G0 X1 L2", "L word with no G10, cutter compensation, canned cycle, digital/analog input, M98 or NURBS code");
	expect_error("P1", "P word with no G2 G3 G4 G10 G64 G5 G5.2 G76 G82 G86 G88 G89 or M50 M51 M52 M53 M62 M63 M64 M65 M66 M98 or user M code to use it");
	expect_error("Q1", "Q word with no G5, G10, G64, G73, G76, G83, M19, M66, M67, M68 or user M code that uses it");
	expect_error("G0 X1 R1", "R word with no g code that uses it");
	expect_error("E1", "E word with no G70, G76, M66, M67 or M68 to use it");
	expect_error("$0", "$ (spindle selection) word with no M3, M4, M5, M19, M51, G33, G33.1, G76, G95, G96 or G97 to use it");
	expect_error("$1 M3", "Spindle number out of range (only spindle 0 is configured)");
}

TEST(InterpModal, UnitsConvertToMachineUnits)
{
	Prog r("G20 G0 X1 F10\nG1 Y1\nG21 G0 X1\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.moves(), (std::vector<std::string>{"STRAIGHT_TRAVERSE(25.4000, 0.0000, 0.0000)",
	                                              "STRAIGHT_FEED(25.4000, 25.4000, 0.0000)",
	                                              "STRAIGHT_TRAVERSE(1.0000, 25.4000, 0.0000)"}));
	auto feeds = r.calls({"SET_FEED_RATE", "USE_LENGTH_UNITS"});
	EXPECT_EQ(feeds[0], "SET_FEED_RATE(10.0000)");   // F comes before G20 in a block
	EXPECT_EQ(feeds[1], "USE_LENGTH_UNITS(CANON_UNITS_INCHES)");
	EXPECT_EQ(feeds[2], "SET_FEED_RATE(254.0000)");
	rs274::Config inch;
	inch.machine_units = rs274::Units::INCH;
	Prog i("G21 G0 X25.4\nM2\n", inch);
	EXPECT_EQ(i.moves(), std::vector<std::string>{"STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000)"});
}

TEST(InterpModal, FeedModes)
{
	Prog r("G93 G1 X1 F2\nG94 F100 G1 X2\nG95 F0.1 G1 X3\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.calls({"SET_FEED"}),
	          (std::vector<std::string>{"SET_FEED_MODE(0, INVERSE_TIME)", "SET_FEED_RATE(0.0000)",
	                                    "SET_FEED_RATE(2.0000)", "SET_FEED_MODE(0, UNITS_PER_MINUTE)",
	                                    "SET_FEED_RATE(0.0000)", "SET_FEED_RATE(100.0000)",
	                                    "SET_FEED_MODE(0, UNITS_PER_REVOLUTION)", "SET_FEED_RATE(0.1000)",
	                                    "SET_FEED_MODE(0, UNITS_PER_MINUTE)", "SET_FEED_RATE(0.0000)"}));
	expect_error("G93 G1 X1", "F word missing with inverse time g1 move");
	expect_error("G93 G2 X1 Y1 R1", "F word missing with inverse time arc move");
	expect_error("G1 X1", "Cannot do g1 with zero feed rate");
	expect_error("F-1", "Negative f word used");
}

TEST(InterpModal, PathControlPlaneDistance)
{
	Prog r("G61\nG61.1\nG64 P0.05 Q0.02\nG18\nG19\nG17.1\nG17\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.calls({"SET_MOTION_CONTROL_MODE", "SET_NAIVECAM", "SELECT_PLANE"}),
	          (std::vector<std::string>{"SET_MOTION_CONTROL_MODE(CANON_EXACT_PATH, 0.0000)",
	                                    "SET_MOTION_CONTROL_MODE(CANON_EXACT_STOP, 0.0000)",
	                                    "SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, 0.0500)",
	                                    "SET_NAIVECAM_TOLERANCE(0.0200)",
	                                    "SELECT_PLANE(CANON_PLANE_XZ)", "SELECT_PLANE(CANON_PLANE_YZ)",
	                                    "SELECT_PLANE(CANON_PLANE_UV)", "SELECT_PLANE(CANON_PLANE_XY)",
	                                    "SELECT_PLANE(CANON_PLANE_XY)"}));
	expect_error("G17.1 G2 X1 Y1 R1 F1", "Arcs and canned cycles are not supported in the UV, UW and VW planes");
}

TEST(InterpModal, LatheDiameterMode)
{
	Prog r("G7 G0 X10\nG8 G0 X10\nM2\n");
	EXPECT_EQ(r.moves(), (std::vector<std::string>{"STRAIGHT_TRAVERSE(5.0000, 0.0000, 0.0000)",
	                                              "STRAIGHT_TRAVERSE(10.0000, 0.0000, 0.0000)"}));
}

TEST(InterpModal, ProgramEndResets)
{
	Prog r("G55\nG18 G91 G93 G41.1 D0 M4 S100 M7 G0 X1\nM30\n");
	ASSERT_TRUE(r.ok()) << r.error();
	auto v = r.calls();
	std::vector<std::string> tail(v.end() - 13, v.end());
	EXPECT_EQ(tail, (std::vector<std::string>{
		"STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000)",
		"SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000)", "SET_XY_ROTATION(0.0000)",
		"SELECT_PLANE(CANON_PLANE_XY)", "SET_FEED_MODE(0, UNITS_PER_MINUTE)", "SET_FEED_RATE(0.0000)",
		"ENABLE_FEED_OVERRIDE()", "ENABLE_SPEED_OVERRIDE(0)", "STOP_SPINDLE_TURNING(0)", "MIST_OFF()",
		"FLOOD_OFF()", "PALLET_SHUTTLE()", "PROGRAM_END()"}));
}
