// SPDX-License-Identifier: GPL-2.0-or-later
// tools.cpp - the tool table file (emcrsh-and-halui.md 2.5): "T<n> P<pocket> [X..W D I J
// Q] [;remark]" one tool per line; a bad line is an error naming file and line.
#include <cctype>
#include <cstring>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "impl.hpp"
#include "ini/axes.hpp"

namespace rs274 {

void Interp::Impl::load_tool_table()
{
	tools.clear();
	if (cfg.tool_table.empty())
		return;
	std::ifstream in(cfg.tool_table);
	if (!in)
		fail("%s: cannot open tool table", cfg.tool_table.c_str());
	std::string line;
	int lineno = 0;
	while (std::getline(in, line)) {
		lineno++;
		if (line.size() > 256)
			fail("%s:%d: tool table line too long", cfg.tool_table.c_str(), lineno);
		std::string remark;
		size_t semi = line.find(';');
		if (semi != std::string::npos) {
			remark = line.substr(semi + 1);
			line.erase(semi);
		}
		std::istringstream words(line);
		std::string w;
		Tool t;
		int number = -1;
		bool has_pocket = false, any = false;
		while (words >> w) {
			any = true;
			char l = (char)std::toupper((unsigned char)w[0]);
			const char* s = w.c_str() + 1;
			char* end;
			double v = std::strtod(s, &end);
			if (end == s || *end)
				fail("%s:%d: bad tool table field '%s'", cfg.tool_table.c_str(), lineno, w.c_str());
			int ax = hal::ini::axis_index(l);
			if (l == 'T') {
				number = (int)v;
			} else if (l == 'P') {
				t.pocket = (int)v;
				has_pocket = true;
			} else if (ax >= 0) {
				t.offset[ax] = v;
			} else if (l == 'D') {
				t.diameter = v;
			} else if (l == 'I') {
				t.frontangle = v;
			} else if (l == 'J') {
				t.backangle = v;
			} else if (l == 'Q') {
				t.orientation = (int)v;
			} else {
				fail("%s:%d: unknown tool table field '%s'", cfg.tool_table.c_str(), lineno, w.c_str());
			}
		}
		if (!any)
			continue;
		if (number < 0 || !has_pocket)
			fail("%s:%d: tool table line needs T and P", cfg.tool_table.c_str(), lineno);
		if (tools.count(number))
			fail("%s:%d: tool %d listed twice", cfg.tool_table.c_str(), lineno, number);
		t.remark = remark;
		tools[number] = t;
	}
}

const Tool* Interp::Impl::tool(int n) const
{
	auto it = tools.find(n);
	return it == tools.end() ? nullptr : &it->second;
}

}  // namespace rs274
