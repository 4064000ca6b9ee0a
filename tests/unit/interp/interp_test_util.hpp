// SPDX-License-Identifier: GPL-2.0-or-later
// Helpers for the interpreter's unit tests: run a program (text) through librs274 with
// the printing canon and look at the calls, the status and the parameters.
#pragma once
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "rs274/interp.hpp"
#include "rs274/print_canon.hpp"

namespace interp_test {

struct Prog {
	std::ostringstream out;
	rs274::PrintCanon canon;
	rs274::Interp interp;
	rs274::Status status = rs274::Status::OK;

	explicit Prog(const std::string& program, rs274::Config cfg = {}, bool block_delete = false)
	    : canon(out, cfg.axes), interp(canon, cfg)
	{
		interp.set_block_delete(block_delete);
		if (!interp.init()) {
			status = rs274::Status::ERROR;
			return;
		}
		out.str("");   // the init calls are the same for every test
		interp.open_text("t.ngc", program);
		status = interp.run();
	}
	bool ok() const { return status == rs274::Status::END; }
	std::string error() const { return interp.error().message; }
	int error_line() const { return interp.error().line; }
	// The printed calls without their line numbers, optionally only those starting with `prefix`s.
	std::vector<std::string> calls(std::initializer_list<const char*> prefixes = {}) const
	{
		std::vector<std::string> v;
		std::istringstream in(out.str());
		std::string l;
		while (std::getline(in, l)) {
			std::string c = l.substr(l.find(' ') + 1);
			bool keep = prefixes.size() == 0;
			for (const char* p : prefixes)
				if (c.rfind(p, 0) == 0)
					keep = true;
			if (keep)
				v.push_back(c);
		}
		return v;
	}
	std::vector<std::string> moves() const
	{
		return calls({"STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "ARC_FEED", "STRAIGHT_PROBE", "RIGID_TAP"});
	}
	double param(int i) const { return interp.parameter(i); }
	double named(const std::string& n) const
	{
		double v = -12345;
		interp.named_parameter(n, v);
		return v;
	}
};

// Runs `program` + "\nM2" and expects an error with this message on this line.
inline void expect_error(const std::string& program, const std::string& message, int line = 1,
                         rs274::Config cfg = {})
{
	Prog r(program + "\nM2\n", cfg);
	EXPECT_EQ(r.status, rs274::Status::ERROR) << program;
	EXPECT_EQ(r.error(), message) << program;
	EXPECT_EQ(r.error_line(), line) << program;
}

inline rs274::Config mill()
{
	rs274::Config c;
	c.startup_code = "G17 G21 G40 G49 G54 G80 G90 G94 G98 G64";
	return c;
}

}  // namespace interp_test
