// SPDX-License-Identifier: GPL-2.0-or-later
// #<_hal[...]> and #<_ini[...]...> from the interpreter's side: librs274 has no HAL;
// it asks its canon (Canon::hal_value), which task answers from HAL. Here a canon
// answers from a map and records what it was asked, and when.
#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "rs274/interp.hpp"
#include "rs274/print_canon.hpp"

namespace {

struct HalCanon : rs274::PrintCanon {
	explicit HalCanon(std::ostream& o) : PrintCanon(o, "XYZ") {}
	std::map<std::string, double> hal;
	std::vector<std::string> asked;
	bool hal_value(const std::string& name, double& value) override
	{
		asked.push_back(name);
		auto it = hal.find(name);
		if (it == hal.end())
			return false;
		value = it->second;
		// the value changes after each read: a second read must ask again
		it->second += 1;
		return true;
	}
};

struct HalRun {
	std::ostringstream out;
	HalCanon canon{out};
	rs274::Interp interp;
	rs274::Status status;
	HalRun(const std::string& program, rs274::Config cfg, std::map<std::string, double> hal = {})
	    : interp(canon, (cfg.startup_code = "G21", cfg))
	{
		canon.hal = std::move(hal);
		EXPECT_TRUE(interp.init());
		interp.open_text("t.ngc", program);
		status = interp.run();
	}
};

}  // namespace

TEST(InterpHalVars, AskTheCanonAtEveryRead)
{
	HalRun r("#1 = #<_hal[Motion.Spindle-Speed-Out]>\n#2 = #<_hal[motion.spindle-speed-out]>\nM2\n", {},
	      {{"motion.spindle-speed-out", 1200}});
	ASSERT_EQ(r.status, rs274::Status::END) << r.interp.error().message;
	EXPECT_EQ(r.interp.parameter(1), 1200);
	EXPECT_EQ(r.interp.parameter(2), 1201);
	// names reach the canon lower-cased (gcode.md: lower-case names only)
	ASSERT_EQ(r.canon.asked.size(), 2u);
	EXPECT_EQ(r.canon.asked[0], "motion.spindle-speed-out");
}

TEST(InterpHalVars, UnknownNameIsNotDefined)
{
	HalRun r("#1 = #<_hal[no.such.pin]>\nM2\n", {});
	EXPECT_EQ(r.status, rs274::Status::ERROR);
	EXPECT_EQ(r.interp.error().message, "Named parameter #<_hal[no.such.pin]> not defined");
	EXPECT_EQ(r.canon.asked, std::vector<std::string>{"no.such.pin"});
}

TEST(InterpHalVars, OffWithoutHalPinVars)
{
	rs274::Config c;
	c.hal_pin_vars = false;
	HalRun r("#1 = #<_hal[a.b]>\nM2\n", c, {{"a.b", 1}});
	EXPECT_EQ(r.status, rs274::Status::ERROR);
	EXPECT_TRUE(r.canon.asked.empty());
}

TEST(InterpHalVars, ReadOnly)
{
	HalRun r("#<_hal[a.b]> = 3\nM2\n", {}, {{"a.b", 1}});
	EXPECT_EQ(r.status, rs274::Status::ERROR);
	EXPECT_EQ(r.interp.error().message, "Cannot assign to read-only parameter #<_hal[a.b]>");
}

TEST(InterpHalVars, UsableInExpressionsAndConditions)
{
	HalRun r("o1 if [#<_hal[probe.ok]> GT 0.5]\n#3 = [#<_hal[probe.ok]> * 10]\no1 endif\nM2\n", {},
	      {{"probe.ok", 1}});
	ASSERT_EQ(r.status, rs274::Status::END) << r.interp.error().message;
	EXPECT_EQ(r.interp.parameter(3), 20);
}

TEST(InterpIniVars, OffWithoutIniVarsAndTaskFlag)
{
	rs274::Config c;
	c.ini["TRAJ]MAX_LINEAR_VELOCITY"] = "100";
	c.ini_vars = false;
	HalRun off("#1 = #<_ini[traj]max_linear_velocity>\nM2\n", c);
	EXPECT_EQ(off.status, rs274::Status::ERROR);
	c.ini_vars = true;
	c.in_task = true;
	HalRun on("#1 = #<_ini[traj]max_linear_velocity>\n#2 = #<_task>\nM2\n", c);
	ASSERT_EQ(on.status, rs274::Status::END) << on.interp.error().message;
	EXPECT_EQ(on.interp.parameter(1), 100);
	EXPECT_EQ(on.interp.parameter(2), 1);
}
