// SPDX-License-Identifier: GPL-2.0-or-later
// The reader (gcode.md 1): case, blanks, comments, active comments, block delete,
// line numbers, %, words, parameter settings taking effect after the line.
#include <cstdio>
#include <fstream>

#include "interp_test_util.hpp"

using interp_test::expect_error;
using interp_test::Prog;

TEST(InterpLexer, CaseAndBlanksAreIgnored)
{
	Prog r("g0x +0. 12 34y 7\nm2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.moves(), std::vector<std::string>{"STRAIGHT_TRAVERSE(0.1234, 7.0000, 0.0000)"});
}

TEST(InterpLexer, CommentsKeepTheirCase)
{
	Prog r("G0 (Hello World) X1 ; Rest Of Line\n(MSG, Operator Text)\n( msg ,spaced keyword)\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.calls({"COMMENT", "MESSAGE"}),
	          (std::vector<std::string>{"COMMENT(\" Rest Of Line\")", "MESSAGE(\"Operator Text\")",
	                                    "MESSAGE(\"spaced keyword\")"}));
}

TEST(InterpLexer, OnlyTheLastCommentOfALineCounts)
{
	Prog r("(MSG,first) (MSG,second)\nM2\n");
	EXPECT_EQ(r.calls({"MESSAGE"}), std::vector<std::string>{"MESSAGE(\"second\")"});
}

TEST(InterpLexer, CommentErrors)
{
	expect_error("G0 X1 (a (b) c)", "Nested comment found");
	expect_error("G0 X1 (abc", "Unclosed comment found");
	expect_error("G0 X(comment)1", "Bad number format");
}

TEST(InterpLexer, DebugSubstitutesAndCanBeSwitchedOff)
{
	Prog r("#1=2.5 #<width>=3\n(DEBUG,a=#1 w=%.1f#<Width> i=%d#1)\n#5599=0\n(DEBUG,hidden)\n(PRINT,p=%f#1)\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.calls({"MESSAGE", "PRINT"}),
	          (std::vector<std::string>{"MESSAGE(\"a=2.500000 w=3.0 i=2\")", "PRINT(\"p=2.5000\")"}));
}

TEST(InterpLexer, LogFile)
{
	std::string path = ::testing::TempDir() + "interp_log.txt";
	Prog r("#1=4\n(LOGOPEN," + path + ")\n(LOG,value %d#1)\n(LOGCLOSE)\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	std::ifstream f(path);
	std::string line;
	std::getline(f, line);
	EXPECT_EQ(line, "value 4");
	std::remove(path.c_str());
}

TEST(InterpLexer, AbortComment)
{
	expect_error("(ABORT,stop here)", "stop here");
}

TEST(InterpLexer, BlockDelete)
{
	Prog on("/G0 X1\nG0 Y1\nM2\n", {}, true);
	EXPECT_EQ(on.moves(), std::vector<std::string>{"STRAIGHT_TRAVERSE(0.0000, 1.0000, 0.0000)"});
	Prog off("/G0 X1\nG0 Y1\nM2\n", {}, false);
	EXPECT_EQ(off.moves().size(), 2u);
}

TEST(InterpLexer, LineNumbersAreIgnoredErrorsNameFileLines)
{
	Prog r("N10 G0 X1\nN20.5 G0 X2\nN30 G1 X3\nM2\n");
	EXPECT_EQ(r.status, rs274::Status::ERROR);
	EXPECT_EQ(r.error(), "Cannot do g1 with zero feed rate");
	EXPECT_EQ(r.error_line(), 3);
	expect_error("G0 N10 X1", "Line number must come first (n word not at start of line)");
}

TEST(InterpLexer, PercentDelimitedProgram)
{
	Prog r("\n%\nG0 X1\n%\nG0 X99 this is never read\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.moves().size(), 1u);
	Prog open("%\nG0 X1\n");
	EXPECT_EQ(open.error(), "File ended with no percent sign (%)");
	Prog noend("G0 X1\n");
	EXPECT_EQ(noend.error(), "File ended with no percent sign (%) or program end (M2)");
	Prog after("G0 X1\nM30\nG0 X2 this is never read\n");
	EXPECT_TRUE(after.ok());
}

TEST(InterpLexer, ParameterSettingsTakeEffectAfterTheLine)
{
	Prog r("#3=15\n#3=6 G0 X#3\n#4=1 #4=2\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.moves(), std::vector<std::string>{"STRAIGHT_TRAVERSE(15.0000, 0.0000, 0.0000)"});
	EXPECT_EQ(r.param(3), 6);
	EXPECT_EQ(r.param(4), 2);   // the last setting wins
	expect_error("#1 2", "Equal sign missing in parameter setting");
}

TEST(InterpLexer, WordErrors)
{
	expect_error("G0 X1 X2", "Multiple x words on one line");
	expect_error("G0 A1", "Unknown word starting with a");
	expect_error("G0 X1 &", "Unknown word starting with &");
	expect_error("M3 M7 M48 M62 P1 M100", "Too many m codes on line");
	expect_error("G1.55", "Non integer value for integer");
	expect_error(std::string("G0 X1 (") + std::string(250, 'x') + ")", "Command too long");
	expect_error("G0 X", "Missing value at end of line");
}

TEST(InterpLexer, ConfiguredRotaryAxesAreWords)
{
	rs274::Config c;
	c.axes = "XYZA";
	Prog r("G0 X1 A90\nM2\n", c);
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.moves(), std::vector<std::string>{"STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 90.0000)"});
	expect_error("G0 B1", "Unknown word starting with b", 1, c);
}
