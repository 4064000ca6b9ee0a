// SPDX-License-Identifier: GPL-2.0-or-later
// Expressions and parameters (gcode.md 4, 5): precedence, functions, comparisons,
// numbered/named parameters, EXISTS, predefined #<_...> values, errors.
#include <cmath>

#include "interp_test_util.hpp"

using interp_test::expect_error;
using interp_test::Prog;

static double eval(const std::string& expr)
{
	Prog r("#1 = " + expr + "\nM2\n");
	EXPECT_TRUE(r.ok()) << expr << ": " << r.error();
	return r.param(1);
}

TEST(InterpExpr, Precedence)
{
	EXPECT_DOUBLE_EQ(eval("[2 ** 3 + 10 MOD 4 * 2]"), 12);
	EXPECT_DOUBLE_EQ(eval("[1 + 2 * 3]"), 7);
	EXPECT_DOUBLE_EQ(eval("[[1 + 2] * 3]"), 9);
	EXPECT_DOUBLE_EQ(eval("[2 ** 3 ** 2]"), 64);     // left to right
	EXPECT_DOUBLE_EQ(eval("[8 / 2 / 2]"), 2);
	EXPECT_DOUBLE_EQ(eval("[1 + 1 EQ 2]"), 1);       // + binds tighter than EQ
	EXPECT_DOUBLE_EQ(eval("[1 LT 2 AND 3 GT 2]"), 1);
	EXPECT_DOUBLE_EQ(eval("[0 OR 0 XOR 1]"), 1);
	EXPECT_DOUBLE_EQ(eval("[-7 MOD 3]"), 2);
	EXPECT_DOUBLE_EQ(eval("[7 MOD -3]"), 1);
	EXPECT_DOUBLE_EQ(eval("-[2]"), -2);
}

TEST(InterpExpr, Comparisons)
{
	EXPECT_EQ(eval("[1 EQ 1.0000001]"), 1);
	EXPECT_EQ(eval("[1 EQ 1.00001]"), 0);
	EXPECT_EQ(eval("[1 NE 1.0000001]"), 0);
	EXPECT_EQ(eval("[1 LE 0.9999999]"), 1);
	EXPECT_EQ(eval("[1 GE 1.0000001]"), 1);
	EXPECT_EQ(eval("[1 LT 1]"), 0);
	EXPECT_EQ(eval("[1 GT 0.5]"), 1);
}

TEST(InterpExpr, Functions)
{
	EXPECT_NEAR(eval("[ATAN[1]/[1]]"), 45, 1e-12);
	EXPECT_NEAR(eval("[ATAN[1]/[-1]]"), 135, 1e-12);
	EXPECT_NEAR(eval("[SIN[30]]"), 0.5, 1e-12);
	EXPECT_NEAR(eval("[COS[60]]"), 0.5, 1e-12);
	EXPECT_NEAR(eval("[TAN[45]]"), 1, 1e-12);
	EXPECT_NEAR(eval("[ASIN[1]]"), 90, 1e-12);
	EXPECT_NEAR(eval("[ACOS[0]]"), 90, 1e-12);
	EXPECT_NEAR(eval("[EXP[1]]"), M_E, 1e-12);
	EXPECT_NEAR(eval("[LN[EXP[2]]]"), 2, 1e-12);
	EXPECT_EQ(eval("[SQRT[16]]"), 4);
	EXPECT_EQ(eval("[ABS[-3]]"), 3);
	EXPECT_EQ(eval("[FIX[-2.8]]"), -3);
	EXPECT_EQ(eval("[FUP[-2.8]]"), -2);
	EXPECT_EQ(eval("[FIX[-2.5]]"), -3);
	EXPECT_EQ(eval("[FUP[-2.5]]"), -2);
	EXPECT_EQ(eval("[ROUND[-2.5]]"), -3);
	EXPECT_EQ(eval("[ROUND[2.5]]"), 3);
	EXPECT_EQ(eval("abs[-1]"), 1);    // a function is a value without brackets around it
}

TEST(InterpExpr, Exists)
{
	Prog r("#<a> = 1\n#1 = [EXISTS[#<a>]]\n#2 = [EXISTS[#<b>]]\n#3 = EXISTS[#<_x>]\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.param(1), 1);
	EXPECT_EQ(r.param(2), 0);
	EXPECT_EQ(r.param(3), 1);
}

TEST(InterpExpr, Indirection)
{
	Prog r("#2 = 7\n#7 = 42\n#1 = ##2\n#3 = #[1+1]\n#4 = [#2+1]\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.param(1), 42);
	EXPECT_EQ(r.param(3), 7);
	EXPECT_EQ(r.param(4), 8);
}

TEST(InterpExpr, Errors)
{
	expect_error("#1 = [1/0]", "Attempt to divide by zero");
	expect_error("#1 = [1 MOD 0]", "Attempt to divide by zero");
	expect_error("#1 = [ACOS[2]]", "Argument to acos out of range");
	expect_error("#1 = [ASIN[-2]]", "Argument to asin out of range");
	expect_error("#1 = [LN[-1]]", "Zero or negative argument to ln");
	expect_error("#1 = [SQRT[-4]]", "Negative argument to sqrt");
	expect_error("#1 = [[-8] ** [1/3]]", "Attempt to raise negative to non integer power");
	expect_error("#1 = [1 + 2", "Unclosed expression");
	expect_error("#1 = SIN 30", "Left bracket missing after unary operation name");
	expect_error("#1 = [ATAN[1]]", "Slash missing after first atan argument");
	expect_error("#1 = [ATAN[1]/1]", "Left bracket missing after slash with atan");
	expect_error("#1 = [1 ? 2]", "Unknown operation");
	expect_error("#1 = [BOGUS[1]]", "Unknown word where unary operation could be");
	expect_error("#1 = " + std::string(41, '[') + "1" + std::string(41, ']'),
	             "Expression nested too deeply (more than 40 levels)");
}

TEST(InterpParams, NumberedRanges)
{
	expect_error("#5602 = 1", "Parameter number out of range");
	expect_error("#1 = #0", "Parameter number out of range");
	expect_error("#1.5 = 1", "Non integer value for integer");
	for (const char* p : {"#5021 = 1", "#5081 = 1", "#5400 = 1", "#5410 = 1", "#5420 = 1"})
		expect_error(p, "Parameter is readonly");
	Prog r("#5000 = 1\n#31 = 2\nM2\n");
	EXPECT_TRUE(r.ok()) << r.error();
}

TEST(InterpParams, NamedLocalAndGlobal)
{
	Prog r("#<Mixed Case> = 3\n#1 = #<mixedcase>\n#<_glob> = 4\n"
	      "o<s> sub\n#<_in> = [#<_glob> + 1]\n#<local> = 9\no<s> endsub\no<s> call\n"
	      "#2 = #<_in>\n#3 = EXISTS[#<local>]\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.param(1), 3);
	EXPECT_EQ(r.param(2), 5);
	EXPECT_EQ(r.param(3), 0);   // #<local> lived in the subroutine only
	expect_error("#1 = #<undefined>", "Named parameter #<undefined> not defined");
	expect_error("#<_x> = 1", "Cannot assign to read-only parameter #<_x>");
	expect_error("#<abc = 1", "Named parameter not terminated");
}

TEST(InterpParams, Predefined)
{
	Prog r("G20 G91 G0 X1 Y2\nG55\n#1=#<_imperial> #2=#<_incremental> #3=#<_coord_system> #4=#<_x>\n"
	      "#5=#<_motion_mode> #6=#5420 #7=#5021 #8=#<_abs_x> #9=#<_vmajor>\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.param(1), 1);
	EXPECT_EQ(r.param(2), 1);
	EXPECT_EQ(r.param(3), 550);
	EXPECT_NEAR(r.param(4), 1, 1e-12);
	EXPECT_EQ(r.param(5), 0);
	EXPECT_NEAR(r.param(6), 1, 1e-12);
	EXPECT_NEAR(r.param(7), 1, 1e-12);   // program units (inch) although the machine is mm
	EXPECT_NEAR(r.param(8), 1, 1e-12);
	EXPECT_EQ(r.param(9), 2);
}

TEST(InterpParams, IniValues)
{
	rs274::Config c;
	c.ini["AXIS_X]MAX_LIMIT"] = "200.5";
	c.ini["AXIS_X]NAME"] = "text";
	Prog r("#1 = #<_ini[axis_x]max_limit>\nM2\n", c);
	ASSERT_TRUE(r.ok()) << r.error();
	EXPECT_EQ(r.param(1), 200.5);
	expect_error("#1 = #<_ini[axis_x]name>", "INI value #<_ini[axis_x]name> is not a number", 1, c);
	expect_error("#1 = #<_ini[axis_x]nokey>", "Named parameter #<_ini[axis_x]nokey> not defined", 1, c);
	expect_error("#1 = #<_hal[motion.enable]>", "Named parameter #<_hal[motion.enable]> not defined", 1, c);
}
