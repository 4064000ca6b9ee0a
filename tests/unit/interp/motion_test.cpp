// SPDX-License-Identifier: GPL-2.0-or-later
// Motion (gcode.md 8, 9): G0/G1, arcs in every plane, radius and centre format and
// their tolerance rule, turns, helices, polar coordinates, G53, probes, G33/G33.1.
#include "interp_test_util.hpp"

using interp_test::expect_error;
using interp_test::mill;
using interp_test::Prog;
using V = std::vector<std::string>;

TEST(InterpMotion, ArcsInEachPlane)
{
	Prog xy("G17 G2 X1 Y1 I1 F100\nM2\n");
	EXPECT_EQ(xy.moves(), V{"ARC_FEED(1.0000, 1.0000, 1.0000, 0.0000, -1, 1.0000, 1.0000, 0.0000)"});
	Prog xz("G18 G3 Z1 X1 K1 F100\nM2\n");   // first axis Z, second X
	EXPECT_EQ(xz.moves(), V{"ARC_FEED(1.0000, 1.0000, 1.0000, 0.0000, 1, 1.0000, 0.0000, 1.0000)"});
	Prog yz("G19 G2 Y2 Z0 J1 F100\nM2\n");
	EXPECT_EQ(yz.moves(), V{"ARC_FEED(2.0000, 0.0000, 1.0000, 0.0000, -1, 0.0000, 2.0000, 0.0000)"});
	expect_error("G2 X1 Y1 K1 F1", "K word given for arc in xy plane");
	expect_error("G18 G2 X1 Z1 J1 F10", "J word given for arc in xz plane");
	expect_error("G19 G2 Y1 Z1 I1 F10", "I word given for arc in yz plane");
}

TEST(InterpMotion, RadiusFormat)
{
	Prog r("G0 X0 Y0\nG3 X1 Y1 R1 F100\nG0 X0 Y0\nG3 X1 Y1 R-1\nG0 X0 Y0\nG2 X6 Y0 R5\nG0 X0 Y0\nG2 X6 Y0 R-5\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.calls({"ARC_FEED"}),
	          (V{"ARC_FEED(1.0000, 1.0000, 0.0000, 1.0000, 1, 1.0000, 1.0000, 0.0000)",
	             "ARC_FEED(1.0000, 1.0000, 1.0000, 0.0000, 1, 1.0000, 1.0000, 0.0000)",
	             "ARC_FEED(6.0000, 0.0000, 3.0000, -4.0000, -1, 6.0000, 0.0000, 0.0000)",
	             "ARC_FEED(6.0000, 0.0000, 3.0000, 4.0000, -1, 6.0000, 0.0000, 0.0000)"}));
	// a semicircle within the tolerance of the chord
	Prog s("G2 X2 Y0 R0.9995 F1\nM2\n");
	EXPECT_EQ(s.moves(), V{"ARC_FEED(2.0000, 0.0000, 1.0000, 0.0000, -1, 2.0000, 0.0000, 0.0000)"});
	expect_error("G2 X1 Y1 R0.1 F10", "Arc radius too small to reach end point");
	expect_error("G2 X0 Y0 R1 F1", "Current point same as end point of arc");
	expect_error("G2 Z1 R1 F1", "X and y words missing for arc in xy plane");
	expect_error("G18 G2 Y1 R1 F1", "X and z words missing for arc in xz plane");
	expect_error("G2 X1 R1 I1 F1", "Mixed radius ijk format for arc");
	expect_error("G2 X1 Y1 F1", "R i j k words all missing for arc");
	expect_error("G2 X1 Y1 R1", "Cannot make arc with zero feed rate");
}

TEST(InterpMotion, CentreToleranceRule)
{
	Prog ok("G2 X2 Y0 I1.01 F100\nM2\n");
	EXPECT_TRUE(ok.ok()) << ok.error();
	EXPECT_EQ(ok.moves(), V{"ARC_FEED(2.0000, 0.0000, 1.0100, 0.0000, -1, 2.0000, 0.0000, 0.0000)"});
	Prog bad("G2 X2 Y0 I1.1 F100\nM2\n");
	EXPECT_EQ(bad.error().rfind("Radius to end of arc differs from radius to start: ", 0), 0u) << bad.error();
	Prog inch("G20 G2 X2 Y0 I1.01 F100\nM2\n");
	EXPECT_EQ(inch.status, rs274::Status::ERROR);
	rs274::Config loose;
	loose.center_arc_tolerance_inch = 0.03;
	Prog inch_loose("G20 G2 X2 Y0 I1.01 F100\nM2\n", loose);
	EXPECT_TRUE(inch_loose.ok()) << inch_loose.error();
	expect_error("G2 X0.0001 Y0 I0.0001 F1", "Zero radius arc");
}

TEST(InterpMotion, TurnsAndHelix)
{
	Prog r("G2 I5 Z-2 P2 F200\nG3 X10 Y0 I5 P3\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.moves(), (V{"ARC_FEED(0.0000, 0.0000, 5.0000, 0.0000, -2, 0.0000, 0.0000, -2.0000)",
	                        "ARC_FEED(10.0000, 0.0000, 5.0000, 0.0000, 3, 10.0000, 0.0000, -2.0000)"}));
	expect_error("G2 I5 P0 F1", "P value should be 1 or greater with G2 or G3");
	expect_error("G2 I5 P1.5 F1", "P value not an integer with M19 G2 or G3");
}

TEST(InterpMotion, AbsoluteCentre)
{
	Prog r("G0 X2 Y0\nG90.1 G3 X0 Y2 I0 J0 F100\nG91.1\nM2\n");
	EXPECT_EQ(r.calls({"ARC_FEED"}), V{"ARC_FEED(0.0000, 2.0000, 0.0000, 0.0000, 1, 0.0000, 2.0000, 0.0000)"});
	expect_error("G0 X2 Y0\nG90.1 G3 X0 Y2 I0 F100", "J word missing in absolute center arc", 2);
	expect_error("G0 X2 Y0\nG90.1 G3 X0 Y2 J0 F100", "I word missing in absolute center arc", 2);
}

TEST(InterpMotion, Polar)
{
	Prog r("G0 @1 ^90\nG91 G0 @1\nG0 ^90\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.moves(), (V{"STRAIGHT_TRAVERSE(0.0000, 1.0000, 0.0000)", "STRAIGHT_TRAVERSE(0.0000, 2.0000, 0.0000)",
	                        "STRAIGHT_TRAVERSE(-2.0000, 0.0000, 0.0000)"}));
	expect_error("G0 @1 X1", "Cannot specify both polar coordinate and X word");
	expect_error("G0 @1 Y1", "Cannot specify both polar coordinate and Y word");
	expect_error("G18 G0 @1", "Polar coordinates are only allowed in the XY plane (G17)");
	expect_error("G91 G0 @1 ^1", "Incremental motion with polar coordinates is indeterminate when at the origin");
}

TEST(InterpMotion, G53)
{
	Prog r("G10 L2 P1 X10 Z5\nG0 X1 Z1\nG53 G0 X0\nG53 G1 Z-1 F10\nG0 X0\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.moves(), (V{"STRAIGHT_TRAVERSE(11.0000, 0.0000, 6.0000)", "STRAIGHT_TRAVERSE(0.0000, 0.0000, 6.0000)",
	                        "STRAIGHT_FEED(0.0000, 0.0000, -1.0000)", "STRAIGHT_TRAVERSE(10.0000, 0.0000, -1.0000)"}));
	expect_error("G53 G2 X1 Y1 R1 F10", "Must use g0 or g1 with g53");
	expect_error("G91\nG53 G0 X1", "Cannot use g53 incremental", 2);
}

TEST(InterpMotion, Probe)
{
	Prog r("G10 L2 P1 Z1\nG38.2 Z-5 F10\n(DEBUG,%.1f#5063 %d#5070)\nG38.3 X3 F10\nG38.4 X4\nG38.5 X5\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.calls({"STRAIGHT_PROBE", "MESSAGE"}),
	          (V{"STRAIGHT_PROBE(0.0000, 0.0000, -4.0000, G38.2)", "MESSAGE(\"-5.0 0\")",
	             "STRAIGHT_PROBE(3.0000, 0.0000, -4.0000, G38.3)", "STRAIGHT_PROBE(4.0000, 0.0000, -4.0000, G38.4)",
	             "STRAIGHT_PROBE(5.0000, 0.0000, -4.0000, G38.5)"}));
	expect_error("G38.2 Z-1", "Cannot probe with zero feed rate");
	expect_error("G38.2 Z0.001 F1", "Start point too close to probe point");
	expect_error("G93 G38.2 Z-1 F1", "Cannot probe in inverse time feed mode");
}

TEST(InterpMotion, SpindleSynchronized)
{
	Prog r("M3 S500\nG33 Z-10 K1.5\nG33.1 Z-5 K1 I2\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.calls({"START_SPEED", "STOP_SPEED", "STRAIGHT_FEED", "RIGID_TAP"}),
	          (V{"START_SPEED_FEED_SYNCH(0, 1.5000, 0)", "STRAIGHT_FEED(0.0000, 0.0000, -10.0000)",
	             "STOP_SPEED_FEED_SYNCH()", "START_SPEED_FEED_SYNCH(0, 1.0000, 0)",
	             "RIGID_TAP(0.0000, 0.0000, -5.0000, 2.0000)", "STOP_SPEED_FEED_SYNCH()"}));
	expect_error("M3 S100 G33 Z-1", "K word missing with g33/g33.1");
	expect_error("M3 S100 G33 Z-1 K1 F1", "F word used with a g33/g33.1");
	expect_error("G33 Z-1 K1", "Spindle not turning in g33/g33.1");
}

TEST(InterpMotion, Dwell)
{
	Prog r("G4 P1.5\nM2\n");
	EXPECT_EQ(r.calls({"DWELL"}), V{"DWELL(1.5000)"});
	expect_error("G4", "Dwell time missing with g4");
	expect_error("G4 G2 X1 Y1 R1 P1 F1", "G4 not allowed with G2 or G3 because they both use P");
}
