// SPDX-License-Identifier: GPL-2.0-or-later
// O-word flow control and subroutines (gcode.md 6).
#include <cstdio>
#include <fstream>

#include "interp_test_util.hpp"

using interp_test::expect_error;
using interp_test::Prog;
using V = std::vector<std::string>;

TEST(InterpOWord, SubroutineArgumentsAndReturnValue)
{
	Prog r("#1=100 #2=200 #3=300\n"
	      "o<add> sub\n#<sum> = [#1 + #2]\n#31 = #3\no<add> endsub [#<sum>]\n"
	      "o<add> call [2] [3]\n#10=#<_value> #11=#<_value_returned> #12=#1 #13=#2\n"
	      "o200 sub\no200 return [7]\nG0 X99\no200 endsub\n"
	      "o200 call\n#14=#<_value>\no<add> call [1] [1]\n#15=#<_value>\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.param(10), 5);
	EXPECT_EQ(r.param(11), 1);
	EXPECT_EQ(r.param(12), 100);   // #1..#30 restored on return
	EXPECT_EQ(r.param(13), 200);
	EXPECT_EQ(r.param(31), 300);    // #3 kept the caller's value inside
	EXPECT_EQ(r.param(14), 7);
	EXPECT_EQ(r.param(15), 2);
	EXPECT_TRUE(r.moves().empty());
}

TEST(InterpOWord, IfElseifElse)
{
	const char* prog =
	    "o1 if [#1 EQ 1]\n  G0 X1\no1 elseif [#1 EQ 2]\n  G0 X2\no1 elseif [#1 EQ 3]\n  G0 X3\n"
	    "o1 else\n  G0 X4\no1 endif\nM2\n";
	for (int v = 1; v <= 4; v++) {
		Prog r("#1=" + std::to_string(v) + "\n" + prog);
		ASSERT_TRUE(r.ok()) << r.error();
		ASSERT_EQ(r.moves().size(), 1u) << v;
		EXPECT_EQ(r.moves()[0].substr(0, 24), "STRAIGHT_TRAVERSE(" + std::to_string(v) + ".0000") << v;
	}
}

TEST(InterpOWord, Loops)
{
	Prog r("#1=0\no1 do\n#1=[#1+1]\no1 while [#1 LT 3]\n"
	      "#2=0\no2 repeat [4]\n#2=[#2+1]\no2 endrepeat\n"
	      "#3=0 #4=0\no3 while [#3 LT 10]\n#3=[#3+1]\no3 if [#3 EQ 2]\no3 continue\no3 endif\n"
	      "#4=[#4+1]\no3 if [#3 GE 5]\no3 break\no3 endif\no3 endwhile\n"
	      "#5=0\no4 repeat [0]\n#5=1\no4 endrepeat\n"
	      "#6=0\no5 do\n#6=[#6+1]\no5 if [#6 EQ 2]\no5 break\no5 endif\no5 while [1]\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.param(1), 3);
	EXPECT_EQ(r.param(2), 4);
	EXPECT_EQ(r.param(3), 5);
	EXPECT_EQ(r.param(4), 4);
	EXPECT_EQ(r.param(5), 0);
	EXPECT_EQ(r.param(6), 2);
}

TEST(InterpOWord, RecursionAndIndirection)
{
	Prog r("o10 sub\no10 if [#1 GT 0]\no10 call [#1 - 1]\n#<_depth> = [#<_depth> + 1]\no10 endif\no10 endsub\n"
	      "#<_depth> = 0\no10 call [5]\n#1=#<_depth>\n#101=8\no[#101+2] call [0]\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.param(1), 5);
	expect_error("o1 sub\no1 call\no1 endsub\no1 call", "Too many subroutine levels", 2);
}

TEST(InterpOWord, SubroutineFileOnThePath)
{
	std::string dir = ::testing::TempDir() + "interp_subs";
	std::string cmd = "mkdir -p " + dir;
	ASSERT_EQ(system(cmd.c_str()), 0);
	std::ofstream(dir + "/square.ngc") << "o<square> sub\nG1 X#1 F10\nG1 Y#1\no<square> endsub [#1 * #1]\nM2\n";
	std::ofstream(dir + "/wrong.ngc") << "o<other> sub\no<other> endsub\n";
	rs274::Config c;
	c.subroutine_path = {dir + "/missing", dir};
	Prog r("o<square> call [3]\n#1=#<_value>\no<SQUARE> call [2]\nM2\n", c);
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.param(1), 9);
	EXPECT_EQ(r.moves().size(), 4u);
	expect_error("o<nosuch> call", "Unable to find subroutine file nosuch.ngc for o<nosuch> call", 1, c);
	expect_error("o<wrong> call", "File " + dir + "/wrong.ngc does not define o<wrong>", 1, c);
	Prog err("o<square> call [1/0]\nM2\n", c);
	EXPECT_EQ(err.error(), "Attempt to divide by zero");
}

TEST(InterpOWord, ErrorsInsideSubroutineFileNameThatFile)
{
	std::string dir = ::testing::TempDir() + "interp_subs2";
	std::string cmd = "mkdir -p " + dir;
	ASSERT_EQ(system(cmd.c_str()), 0);
	std::ofstream(dir + "/bad.ngc") << "o<bad> sub\nG0 X1\nG1 X2\no<bad> endsub\n";
	rs274::Config c;
	c.subroutine_path = {dir};
	Prog r("o<bad> call\nM2\n", c);
	EXPECT_EQ(r.error(), "Cannot do g1 with zero feed rate");
	EXPECT_EQ(r.interp.error().file, dir + "/bad.ngc");
	EXPECT_EQ(r.error_line(), 3);
}

TEST(InterpOWord, Errors)
{
	expect_error("o100 call", "Unknown oword number");
	expect_error("o1 call " + std::string(31 * 3, ' ').replace(0, 93, [] {
		std::string s;
		for (int i = 0; i < 31; i++)
			s += "[1]";
		return s;
	}()), "Too many subroutine parameters");
	expect_error("o1 sub\nG0 X1", "No matching o1 endsub found");
	expect_error("o1 sub\no2 sub\no2 endsub\no1 endsub", "Nested subroutine definition (o2 sub inside o1)", 2);
	expect_error("o1 return", "o1 return outside a subroutine");
	expect_error("o1 sub\no2 endsub\no1 endsub\no1 call", "o2 endsub does not match the subroutine being run (o1)", 2);
	expect_error("o3 endwhile", "o3 endwhile without a matching while");
	expect_error("o3 endrepeat", "o3 endrepeat without a matching repeat");
	expect_error("o4 break", "o4 break outside a loop with that label");
	expect_error("o4 continue", "o4 continue outside a loop with that label");
	expect_error("o5 if [1] G0 X1", "Unexpected text after o-word statement: g0x1");
	expect_error("o5 while", "Missing [expression] after o-word statement");
	expect_error("o5 if [0]\nG0 X1", "No matching o5 elseif found");
	expect_error("o6 bogus", "Unknown word where unary operation could be");
}

TEST(InterpOWord, LoopLimit)
{
	rs274::Config c;
	c.max_loop_iterations = 1000;
	expect_error("o1 while [1]\no1 endwhile", "Loop o1 exceeded 1000 iterations", 1, c);
	expect_error("o2 repeat [5000]\no2 endrepeat", "Loop o2 exceeded 1000 iterations", 2, c);
	c.max_blocks = 50;
	expect_error("o3 repeat [30]\nG0 X1\no3 endrepeat", "Program exceeded 50 blocks", 3, c);
}
