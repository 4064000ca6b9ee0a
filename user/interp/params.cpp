// SPDX-License-Identifier: GPL-2.0-or-later
// params.cpp - numbered parameters (read-only and computed ranges), named parameters
// (local, global, predefined #<_...>, #<_ini[..]..>, #<_hal[..]>), the parameter file
// (gcode.md 4.2) and the parameter substitution of DEBUG/PRINT/LOG comments.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "impl.hpp"

namespace rs274 {

static bool in(int i, int lo, int hi) { return i >= lo && i <= hi; }

static bool persistent(int i)
{
	if (in(i, 5161, 5169) || in(i, 5181, 5189) || in(i, 5210, 5220))
		return true;
	for (int n = 0; n < 9; n++)
		if (in(i, 5221 + 20 * n, 5230 + 20 * n))
			return true;
	return false;
}

static bool read_only(int i)
{
	return in(i, 5021, 5029) || in(i, 5081, 5089) || in(i, 5400, 5413) || in(i, 5420, 5428);
}

double Interp::Impl::get_param(int i) const
{
	if (i < 1 || i >= MAX_PARAM)
		return 0;
	if (in(i, 5021, 5029))
		return mpos[i - 5021] / unit_factor(i - 5021);
	if (in(i, 5081, 5089))
		return tlo[i - 5081] / unit_factor(i - 5081);
	if (in(i, 5420, 5428))
		return program_pos()[i - 5420];
	if (in(i, 5400, 5413)) {
		if (i == 5400)
			return current_tool;
		const Tool* t = tool(current_tool);
		if (!t)
			return 0;
		if (i <= 5409)
			return t->offset[i - 5401] / unit_factor(i - 5401);
		if (i == 5410)
			return t->diameter / unit_factor(AX_X);
		if (i == 5411)
			return t->frontangle;
		if (i == 5412)
			return t->backangle;
		return t->orientation;
	}
	return params[i];
}

void Interp::Impl::set_param(int i, double v)
{
	if (i < 1 || i >= MAX_PARAM)
		fail("Parameter number out of range");
	if (read_only(i))
		fail("Parameter is readonly");
	params[i] = v;
}

bool Interp::Impl::predefined(const std::string& n, double& v) const
{
	Pos p = program_pos();
	static const char axes[] = "xyzabcuvw";
	for (int a = 0; a < NUM_AXES; a++) {
		if (n == std::string("_") + axes[a]) { v = p[a]; return true; }
		if (n == std::string("_abs_") + axes[a]) { v = mpos[a] / unit_factor(a); return true; }
	}
	const std::map<std::string, double> table = {
		{"_vmajor", 2}, {"_vminor", 9}, {"_line", (double)cur_line},
		{"_motion_mode", (double)motion}, {"_plane", plane == Plane::XY ? 170.0 : plane == Plane::XZ ? 180.0 : 190.0},
		{"_ccomp", (double)comp}, {"_metric", units == Units::MM ? 1.0 : 0.0},
		{"_imperial", units == Units::INCH ? 1.0 : 0.0}, {"_absolute", incremental ? 0.0 : 1.0},
		{"_incremental", incremental ? 1.0 : 0.0},
		{"_inverse_time", feed_mode == FeedMode::INVERSE_TIME ? 1.0 : 0.0},
		{"_units_per_minute", feed_mode == FeedMode::UNITS_PER_MINUTE ? 1.0 : 0.0},
		{"_units_per_rev", feed_mode == FeedMode::UNITS_PER_REV ? 1.0 : 0.0},
		{"_coord_system", coord <= 6 ? 530.0 + 10 * coord : 590.0 + (coord - 6)},
		{"_tool_offset", tlo_mode != 490 ? 1.0 : 0.0}, {"_retract_r_plane", retract_old_z ? 0.0 : 1.0},
		{"_retract_old_z", retract_old_z ? 1.0 : 0.0}, {"_spindle_rpm_mode", css ? 0.0 : 1.0},
		{"_spindle_css_mode", css ? 1.0 : 0.0}, {"_ijk_absolute_mode", ijk_absolute ? 1.0 : 0.0},
		{"_lathe_diameter_mode", lathe_diameter ? 1.0 : 0.0},
		{"_lathe_radius_mode", lathe_diameter ? 0.0 : 1.0}, {"_spindle_on", spindle_dir ? 1.0 : 0.0},
		{"_spindle_cw", spindle_dir == 1 ? 1.0 : 0.0}, {"_mist", mist ? 1.0 : 0.0},
		{"_flood", flood ? 1.0 : 0.0}, {"_speed_override", speed_override ? 1.0 : 0.0},
		{"_feed_override", feed_override ? 1.0 : 0.0}, {"_adaptive_feed", adaptive ? 1.0 : 0.0},
		{"_feed_hold", feed_hold ? 1.0 : 0.0}, {"_feed", feed}, {"_rpm", speed},
		{"_current_tool", (double)current_tool}, {"_current_pocket", (double)current_pocket},
		{"_selected_tool", (double)selected_tool}, {"_selected_pocket", (double)selected_pocket},
		{"_task", cfg.in_task ? 1.0 : 0.0}, {"_call_level", (double)frames.size() - 1}, {"_remap_level", 0},
	};
	auto it = table.find(n);
	if (it == table.end())
		return false;
	v = it->second;
	return true;
}

bool Interp::Impl::get_named(const std::string& n, double& v)
{
	if (n[0] != '_') {
		auto& loc = frames.back().locals;
		auto it = loc.find(n);
		if (it == loc.end())
			return false;
		v = it->second;
		return true;
	}
	if (n.compare(0, 5, "_ini[") == 0 && cfg.ini_vars) {
		auto c = ini_cache.find(n);
		if (c != ini_cache.end()) {
			v = c->second;
			return true;
		}
		size_t close = n.find(']');
		if (close == std::string::npos)
			return false;
		std::string key = n.substr(5, close - 5) + "]" + n.substr(close + 1);
		for (char& ch : key)
			ch = (char)std::toupper((unsigned char)ch);
		auto it = cfg.ini.find(key);
		if (it == cfg.ini.end())
			return false;
		char* end;
		v = std::strtod(it->second.c_str(), &end);
		if (end == it->second.c_str())
			fail("INI value #<%s> is not a number", n.c_str());
		ini_cache[n] = v;
		return true;
	}
	if (n.compare(0, 5, "_hal[") == 0 && cfg.hal_pin_vars && n.back() == ']')
		return canon.hal_value(n.substr(5, n.size() - 6), v);
	if (n == "_value" || n == "_value_returned") {
		auto it = globals.find(n);
		v = it == globals.end() ? 0 : it->second;
		return true;
	}
	if (predefined(n, v))
		return true;
	auto it = globals.find(n);
	if (it == globals.end())
		return false;
	v = it->second;
	return true;
}

void Interp::Impl::set_named(const std::string& n, double v)
{
	double dummy;
	bool global = n[0] == '_';
	if (global && (predefined(n, dummy) || n.compare(0, 5, "_ini[") == 0 ||
	               n.compare(0, 5, "_hal[") == 0))
		fail("Cannot assign to read-only parameter #<%s>", n.c_str());
	auto& map = global ? globals : frames.back().locals;
	if (map.size() >= MAX_NAMED_PARAMS && map.find(n) == map.end())
		fail("Too many named parameters (limit %zu)", MAX_NAMED_PARAMS);
	map[n] = v;
}

void Interp::Impl::load_param_file()
{
	if (cfg.parameter_file.empty())
		return;
	std::ifstream f(cfg.parameter_file);
	if (!f)
		return;   // a new file: every parameter starts at 0 and the file is written at exit
	std::string line;
	int lineno = 0, last = 0;
	while (std::getline(f, line)) {
		lineno++;
		const char* s = line.c_str();
		while (*s == ' ' || *s == '\t')
			s++;
		if (!std::isdigit((unsigned char)*s))
			continue;
		char* end;
		long idx = std::strtol(s, &end, 10);
		if (*end != ' ' && *end != '\t')
			continue;
		char* vend;
		double v = std::strtod(end, &vend);
		if (vend == end)
			continue;
		if (idx <= last)
			fail("%s:%d: Parameter file out of order", cfg.parameter_file.c_str(), lineno);
		if (idx < 1 || idx >= MAX_PARAM)
			fail("%s:%d: Parameter number out of range", cfg.parameter_file.c_str(), lineno);
		last = (int)idx;
		params[idx] = v;
		param_in_file[idx] = 1;
	}
}

bool Interp::Impl::write_param_file(const std::string& path)
{
	std::string tmp = path + ".new";
	std::FILE* f = std::fopen(tmp.c_str(), "w");
	if (!f) {
		err = {path, 0, "cannot write parameter file " + tmp};
		return false;
	}
	for (int i = 1; i < MAX_PARAM; i++)
		if (param_in_file[i] || persistent(i))
			std::fprintf(f, "%d\t%f\n", i, params[i]);
	if (std::fclose(f) != 0) {
		err = {path, 0, "cannot write parameter file " + tmp};
		return false;
	}
	std::string bak = path + ".bak";
	if (::access(path.c_str(), F_OK) == 0) {
		::unlink(bak.c_str());
		if (::link(path.c_str(), bak.c_str()) != 0)
			std::rename(path.c_str(), bak.c_str());
	}
	if (std::rename(tmp.c_str(), path.c_str()) != 0) {
		err = {path, 0, "cannot rename " + tmp + " to " + path};
		return false;
	}
	return true;
}

// "#n", "#<name>", optionally preceded by a format %d, %f, %.Nf (gcode.md 1).
std::string Interp::Impl::substitute(const std::string& text)
{
	std::string out;
	std::string pending_fmt = "%lf";
	for (size_t i = 0; i < text.size(); i++) {
		char c = text[i];
		if (c == '%') {
			size_t j = i + 1;
			std::string f;
			if (j < text.size() && text[j] == 'd') {
				f = "%.0f";
				j++;
			} else if (j < text.size() && text[j] == 'f') {
				f = "%.4f";
				j++;
			} else if (j + 2 < text.size() && text[j] == '.' && std::isdigit((unsigned char)text[j + 1]) &&
			           text[j + 2] == 'f') {
				f = std::string("%.") + text[j + 1] + "f";
				j += 3;
			}
			if (!f.empty() && j < text.size() && text[j] == '#') {
				pending_fmt = f;
				i = j - 1;
				continue;
			}
			out += c;
			continue;
		}
		if (c != '#') {
			out += c;
			continue;
		}
		double v = 0;
		bool ok = false;
		size_t j = i + 1;
		if (j < text.size() && text[j] == '<') {
			size_t e = text.find('>', j);
			if (e != std::string::npos) {
				std::string name;
				for (size_t k = j + 1; k < e; k++)
					if (text[k] != ' ' && text[k] != '\t')
						name += (char)std::tolower((unsigned char)text[k]);
				ok = !name.empty() && get_named(name, v);
				i = e;
			}
		} else if (j < text.size() && std::isdigit((unsigned char)text[j])) {
			long idx = 0;
			while (j < text.size() && std::isdigit((unsigned char)text[j]) && idx < 100000)
				idx = idx * 10 + (text[j++] - '0');
			ok = idx >= 1 && idx < MAX_PARAM;
			if (ok)
				v = get_param((int)idx);
			i = j - 1;
		} else {
			out += c;
			continue;
		}
		out += ok ? fmt(pending_fmt.c_str(), v) : std::string("######");
		pending_fmt = "%lf";
	}
	return out;
}

}  // namespace rs274
