// SPDX-License-Identifier: GPL-2.0-or-later
// Fanuc-style subprograms (gcode.md 6): M98 P<n> [L<count>] runs O<n> ... M99 of the
// same file; #1-#30 are global there; L0 skips; M99 in the main program restarts it;
// DISABLE_FANUC_STYLE_SUB; mixing with o-word subroutines is an error.
#include "interp_test_util.hpp"

using interp_test::expect_error;
using interp_test::Prog;
using V = std::vector<std::string>;

TEST(InterpFanuc, CallRepeatNestAndSkip)
{
	Prog r("O1 (main)\n#1 = 0\nM98 P100 L3\n#2 = #1\nM98 P200\nM98 P100 L0\nG0 X#1\nM30\n"
	       "O100 (sub)\n#1 = [#1 + 1]\nG0 Y#1\nM99\n"
	       "O200\nM98 P100\nM99\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V want = {"STRAIGHT_TRAVERSE(0.0000, 1.0000, 0.0000)", "STRAIGHT_TRAVERSE(0.0000, 2.0000, 0.0000)",
	          "STRAIGHT_TRAVERSE(0.0000, 3.0000, 0.0000)", "STRAIGHT_TRAVERSE(0.0000, 4.0000, 0.0000)",
	          "STRAIGHT_TRAVERSE(4.0000, 4.0000, 0.0000)"};
	EXPECT_EQ(r.moves(), want);
	EXPECT_EQ(r.param(2), 3);   // #1 is global: the caller sees the subprogram's value
	EXPECT_EQ(r.param(1), 4);
}

TEST(InterpFanuc, SubprogramReachedInSequenceIsSkipped)
{
	Prog r("G0 X1\nO5\nG0 X2\nM99\nG0 X3\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	V want = {"STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000)", "STRAIGHT_TRAVERSE(3.0000, 0.0000, 0.0000)"};
	EXPECT_EQ(r.moves(), want);
}

TEST(InterpFanuc, M99InMainRestartsIt)
{
	// endless: it runs until the block limit stops it, the moves repeating
	rs274::Config c;
	c.max_blocks = 7;
	Prog r("%\nO1\n#1 = [#1 + 1]\nG0 X#1\nM99\n%\n", c);
	EXPECT_EQ(r.status, rs274::Status::ERROR);
	EXPECT_EQ(r.error(), "Program exceeded 7 blocks");
	V want = {"STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000)", "STRAIGHT_TRAVERSE(2.0000, 0.0000, 0.0000)"};
	EXPECT_EQ(r.moves(), want);
	EXPECT_EQ(r.error_line(), 5);   // the second M99 is block 8
}

TEST(InterpFanuc, M99RestartLimitEndsTheProgram)
{
	rs274::Config c;
	c.max_m99_restarts = 2;
	Prog r("#1 = [#1 + 1]\nG0 X#1\nM99\n", c);
	ASSERT_TRUE(r.ok()) << r.error();
	std::vector<std::string> want = {"STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000)",
	                                 "STRAIGHT_TRAVERSE(2.0000, 0.0000, 0.0000)",
	                                 "STRAIGHT_TRAVERSE(3.0000, 0.0000, 0.0000)"};
	EXPECT_EQ(r.moves(), want);
}

TEST(InterpFanuc, Errors)
{
	expect_error("M98", "P word missing with M98");
	expect_error("M98 P7", "Unknown program number o7 for M98");
	expect_error("M98 P1.5", "P value with M98 must be a non-negative integer program number");
	expect_error("M98 P1 L-1", "Negative l word used");
	expect_error("G0 X1\nO5\nG0 X2", "No M99 found for o5", 2);
	expect_error("G0 X1\nO5\nG0 X2\nO6\nM99", "o6 starts before the M99 of o5", 4);
	expect_error("O1\nM98 P1\nM99", "Too many subroutine levels", 2);
	expect_error("O<x>", "Fanuc-style program number o<x> must be a number");
	const char* mix = "Cannot mix Fanuc-style (M98/M99) and o-word (sub/call) subroutines in one program";
	expect_error("o100 sub\no100 endsub\nM98 P1\nO1\nM99", mix, 3);
	expect_error("M98 P1 L0\no100 sub\no100 endsub", mix, 2);
	expect_error("o1 sub\nM99\no1 endsub\no1 call", mix, 2);
	rs274::Config c;
	c.disable_fanuc_style_sub = true;
	expect_error("M98 P1", "Unknown m code used: M98", 1, c);
	expect_error("M99", "Unknown m code used: M99", 1, c);
	expect_error("G0 X1\nO5", "o5 without a statement (Fanuc-style programs are disabled)", 2, c);
}

TEST(InterpFanuc, MdiM99DoesNothing)
{
	std::ostringstream out;
	rs274::PrintCanon canon(out, "XYZ");
	rs274::Interp in(canon, {});
	ASSERT_TRUE(in.init());
	EXPECT_EQ(in.execute_mdi("M99"), rs274::Status::OK);
	EXPECT_EQ(in.execute_mdi("G0 X1"), rs274::Status::OK);
}
