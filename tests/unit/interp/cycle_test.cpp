// SPDX-License-Identifier: GPL-2.0-or-later
// Canned cycles G73, G74, G81-G89 (gcode.md 10), sticky words, other planes, G76.
#include "interp_test_util.hpp"

using interp_test::expect_error;
using interp_test::Prog;
using V = std::vector<std::string>;

static std::string T(double x, double y, double z)
{
	char b[128];
	snprintf(b, sizeof b, "STRAIGHT_TRAVERSE(%.4f, %.4f, %.4f)", x, y, z);
	return b;
}
static std::string F(double x, double y, double z)
{
	char b[128];
	snprintf(b, sizeof b, "STRAIGHT_FEED(%.4f, %.4f, %.4f)", x, y, z);
	return b;
}

TEST(InterpCycles, G81RetractModes)
{
	Prog r("G0 X1 Y2 Z3\nG98 G81 X4 Y5 Z1.5 R2.8 F100\nG80\nG0 X1 Y2 Z3\nG99 G81 X4 Y5 Z1.5 R2.8\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.moves(), (V{T(1, 2, 3), T(4, 5, 3), T(4, 5, 2.8), F(4, 5, 1.5), T(4, 5, 3), T(1, 2, 3),
	                        T(4, 5, 3), T(4, 5, 2.8), F(4, 5, 1.5), T(4, 5, 2.8)}));
}

TEST(InterpCycles, StickyWordsAndSeries)
{
	// R and Z stay while the cycle stays; the initial level stays for the series
	Prog r("G0 Z10\nG98 G81 X1 Y1 Z-1 R2 F10\nX2\nG80\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.moves(), (V{T(0, 0, 10), T(1, 1, 10), T(1, 1, 2), F(1, 1, -1), T(1, 1, 10), T(2, 1, 10),
	                        T(2, 1, 2), F(2, 1, -1), T(2, 1, 10)}));
}

TEST(InterpCycles, DwellBoreAndTapCycles)
{
	Prog r("G0 Z5\nM3 S100\nG99 G82 X1 Z-1 R1 P0.5 F10\nG85 X2 Z-1 R1\nG86 X3 Z-1 R1 P1\nG89 X4 Z-1 R1 P2\nG88 X5 Z-1 R1 P1\nG84 X6 Z-1 R1\nG80\nM4\nG74 X7 Z-1 R1\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V v = r.calls({"STRAIGHT", "DWELL", "STOP_SPINDLE", "START_SPINDLE", "PROGRAM_STOP", "ENABLE_", "DISABLE_"});
	V want = {
		T(0, 0, 5), "START_SPINDLE_CLOCKWISE(0)",
		T(1, 0, 5), T(1, 0, 1), F(1, 0, -1), "DWELL(0.5000)", T(1, 0, 1),                                   // G82
		T(2, 0, 1), F(2, 0, -1), F(2, 0, 1), T(2, 0, 1),                                                    // G85
		T(3, 0, 1), F(3, 0, -1), "DWELL(1.0000)", "STOP_SPINDLE_TURNING(0)", T(3, 0, 1), "START_SPINDLE_CLOCKWISE(0)",  // G86
		T(4, 0, 1), F(4, 0, -1), "DWELL(2.0000)", F(4, 0, 1),                                               // G89
		T(5, 0, 1), F(5, 0, -1), "DWELL(1.0000)", "STOP_SPINDLE_TURNING(0)", "PROGRAM_STOP()", "START_SPINDLE_CLOCKWISE(0)",  // G88
		T(5, 0, 1),   // G88 leaves the tool at the bottom: the next cycle starts with a move up to R
		T(6, 0, 1), "DISABLE_FEED_OVERRIDE()", "DISABLE_SPEED_OVERRIDE(0)", F(6, 0, -1), "STOP_SPINDLE_TURNING(0)",
		"START_SPINDLE_COUNTERCLOCKWISE(0)", F(6, 0, 1), "STOP_SPINDLE_TURNING(0)", "START_SPINDLE_CLOCKWISE(0)",
		"ENABLE_FEED_OVERRIDE()", "ENABLE_SPEED_OVERRIDE(0)",                                               // G84 (no P: no dwell)
		"START_SPINDLE_COUNTERCLOCKWISE(0)",
		T(7, 0, 1), "DISABLE_FEED_OVERRIDE()", "DISABLE_SPEED_OVERRIDE(0)", F(7, 0, -1), "STOP_SPINDLE_TURNING(0)",
		"START_SPINDLE_CLOCKWISE(0)", F(7, 0, 1), "STOP_SPINDLE_TURNING(0)", "START_SPINDLE_COUNTERCLOCKWISE(0)",
		"ENABLE_FEED_OVERRIDE()", "ENABLE_SPEED_OVERRIDE(0)",                                               // G74
	};
	EXPECT_EQ(V(v.begin(), v.begin() + std::min(v.size(), want.size())), want);
}

TEST(InterpCycles, BackBore)
{
	Prog r("G0 Z5\nM3 S100\nG98 G87 X1 Y1 Z-2 R2 I0.5 J0 K-1 F10\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.moves(), (V{T(0, 0, 5), T(1, 1, 5), T(1, 1, 2), T(1.5, 1, 2), T(1.5, 1, -2), T(1, 1, -2), F(1, 1, -1),
	                        F(1, 1, -2), T(1.5, 1, -2), T(1.5, 1, 5), T(1, 1, 5)}));
	expect_error("M3 G87 X1 Z-1 R1 F1", "I word missing with g87");
}

TEST(InterpCycles, OtherPlanes)
{
	Prog r("G18 G0 Y5\nG98 G81 X1 Z1 Y-1 R1 F10\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.moves(), (V{T(0, 5, 0), T(1, 5, 1), T(1, 1, 1), F(1, -1, 1), T(1, 5, 1)}));
	expect_error("G18 G81 X1 Z1 R1 F1", "Y value unspecified in xz plane canned cycle");
	expect_error("G19 G81 Y1 X3 R2 F1", "R less than x in cycle in yz plane");
}

TEST(InterpCycles, Errors)
{
	rs274::Config c;
	c.axes = "XYZA";
	expect_error("G81 X1 Z-1 R1 A1 F1", "Cannot put an a in canned cycle", 1, c);
	expect_error("G81 X1 Z-1 R1 L0 F1", "Cannot do zero repeats of cycle");
	expect_error("G81 X1 Z-1 F1", "R clearance plane unspecified in cycle");
	expect_error("G81 X1 R1 F1", "Z value unspecified in xy plane canned cycle");
	expect_error("G81 X1 Y1 Z1 R0 F10", "R less than z in cycle in xy plane");
	expect_error("G83 X1 Z-1 R1 Q-1 F1", "Negative or zero q value used");
	expect_error("G73 X1 Z-1 R1 F1", "Q word missing with g73");
	expect_error("G82 X1 Z-1 R1 F1", "Dwell time p word missing with g82");
	expect_error("G86 X1 Z-1 R1 P1 F1", "Spindle not turning in g86");
	expect_error("G84 X1 Z-1 R1 F1", "Spindle not turning clockwise in g84");
	expect_error("M4 G84 X1 Z-1 R1 F1", "Spindle turning counterclockwise in G84");
	expect_error("M3 G74 X1 Z-1 R1 F1", "Spindle not turning counterclockwise in g74");
	expect_error("G93 G81 X1 Z-1 R1 F1", "Cannot use inverse time feed with canned cycles");
}

TEST(InterpCycles, Threading)
{
	Prog r("G18 G0 X10 Z2\nM3 S200\nG76 P1.5 Z-10 I-1 J0.5 K1 R2 H1\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	// depth n = 0.5*n^(1/2): 0.5, 0.7071, 0.866, then full depth 1, then one spring pass
	V f = r.calls({"STRAIGHT_FEED"});
	ASSERT_EQ(f.size(), 5u);
	EXPECT_EQ(f[0], "STRAIGHT_FEED(8.5000, 0.0000, -10.0000)");
	EXPECT_EQ(f[1], "STRAIGHT_FEED(8.2929, 0.0000, -10.0000)");
	EXPECT_EQ(f[2], "STRAIGHT_FEED(8.1340, 0.0000, -10.0000)");
	EXPECT_EQ(f[3], "STRAIGHT_FEED(8.0000, 0.0000, -10.0000)");
	EXPECT_EQ(f[4], "STRAIGHT_FEED(8.0000, 0.0000, -10.0000)");
	EXPECT_EQ(r.calls({"START_SPEED"}).size(), 5u);
	EXPECT_EQ(r.moves().back(), T(10, 0, 2));
	expect_error("M3 G76 P1 Z-1 I-1 J0.1 K1", "G76 allowed only in the ZX plane");
	expect_error("G18 M3 G76 P1 Z-1 I-1 J0.1", "K word missing with G76");
	expect_error("G18 M3 G76 P1 Z-1 I-1 J0.1 K1 R0.5", "R value must be 1 or greater with G76");
	expect_error("G18 M3 G76 P1 Z-1 I-1 J0.1 K1 E1", "E value in G76 is more than half the length of the drive line");
}
