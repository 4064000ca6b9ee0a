// SPDX-License-Identifier: GPL-2.0-or-later
// config.cpp - Config::from_ini: the [RS274NGC], [TRAJ], [DISPLAY] and [EMCIO] keys the
// interpreter uses (ini-and-launch.md 2.5). Relative paths are relative to the INI
// file's directory. Every key/value is also kept for #<_ini[section]key>.
#include <cctype>
#include <cstdlib>

#include "ini/ini_reader.hpp"
#include "rs274/interp.hpp"

namespace rs274 {

static std::string trim(const std::string& s)
{
	size_t a = s.find_first_not_of(" \t\r");
	if (a == std::string::npos)
		return "";
	size_t b = s.find_last_not_of(" \t\r");
	return s.substr(a, b - a + 1);
}

static std::string upper(std::string s)
{
	for (char& c : s)
		c = (char)std::toupper((unsigned char)c);
	return s;
}

static std::vector<std::string> path_list(const std::string& v, const std::string& dir)
{
	std::vector<std::string> out;
	size_t start = 0;
	while (start <= v.size()) {
		size_t c = v.find(':', start);
		if (c == std::string::npos)
			c = v.size();
		std::string p = trim(v.substr(start, c - start));
		if (!p.empty())
			out.push_back(p[0] == '/' ? p : dir + "/" + p);
		start = c + 1;
	}
	return out;
}

bool Config::from_ini(const std::string& path, Config& cfg, std::string& error)
{
	auto loaded = hal::ini::IniFile::load(path);
	if (!loaded) {
		error = loaded.error().message;
		return false;
	}
	const hal::ini::IniFile& ini = *loaded;
	std::string dir = ".";
	size_t slash = path.rfind('/');
	if (slash != std::string::npos)
		dir = slash == 0 ? "/" : path.substr(0, slash);
	// #<_ini[section]key> sees what the reader sees: the first occurrence of each key
	// in the first block of its section, names as written (G-code upper-cases its side).
	for (const auto& e : ini.entries())
		if (e.reachable)
			cfg.ini.emplace(e.section + "]" + e.key, e.value);
	auto get = [&](const char* sec, const char* key, std::string& v) {
		auto found = ini.find(sec, key);
		if (!found)
			return false;
		v = *found;
		return true;
	};
	auto rel = [&](const std::string& p) { return p.empty() || p[0] == '/' ? p : dir + "/" + p; };
	bool bad = false;   // the first malformed value, reported as FILE:LINE: [S]K: ...
	auto keep = [&](auto result, auto& out) {
		if (result)
			out = *result;
		else if (!bad) {
			error = result.error().message;
			bad = true;
		}
	};
	auto flag = [&](const char* sec, const char* key, bool& out) { keep(ini.get_bool(sec, key, out), out); };
	auto real = [&](const char* sec, const char* key, double& out) { keep(ini.get_double(sec, key, out), out); };
	std::string v;
	if (get("TRAJ", "LINEAR_UNITS", v)) {
		std::string u = upper(v);
		if (u == "MM" || u == "METRIC" || u == "MILLIMETER")
			cfg.machine_units = Units::MM;
		else if (u == "INCH" || u == "IN" || u == "IMPERIAL")
			cfg.machine_units = Units::INCH;
		else if (std::atof(v.c_str()) > 0.5)
			cfg.machine_units = Units::MM;
		else if (std::atof(v.c_str()) > 0)
			cfg.machine_units = Units::INCH;
		else {
			error = path + ": [TRAJ]LINEAR_UNITS must be mm or inch: " + v;
			return false;
		}
	}
	hal::ini::Reader coords{ini, {}};   // the letters as task and halui read them
	coords.coordinates(cfg.axes);
	if (!coords.err.empty() && !bad) {
		error = coords.err;
		bad = true;
	}
	if (get("RS274NGC", "PARAMETER_FILE", v))
		cfg.parameter_file = rel(v);
	if (get("RS274NGC", "RS274NGC_STARTUP_CODE", v) || get("EMC", "RS274NGC_STARTUP_CODE", v))
		cfg.startup_code = v;
	std::vector<std::string> prefix;
	if (get("DISPLAY", "PROGRAM_PREFIX", v))
		prefix.push_back(rel(v));
	cfg.subroutine_path = prefix;
	cfg.user_m_path = prefix;
	if (get("RS274NGC", "SUBROUTINE_PATH", v))
		for (auto& p : path_list(v, dir))
			cfg.subroutine_path.push_back(p);
	if (get("RS274NGC", "USER_M_PATH", v))
		for (auto& p : path_list(v, dir))
			cfg.user_m_path.push_back(p);
	real("RS274NGC", "ORIENT_OFFSET", cfg.orient_offset);
	real("RS274NGC", "CENTER_ARC_RADIUS_TOLERANCE_INCH", cfg.center_arc_tolerance_inch);
	real("RS274NGC", "CENTER_ARC_RADIUS_TOLERANCE_MM", cfg.center_arc_tolerance_mm);
	flag("RS274NGC", "DISABLE_G92_PERSISTENCE", cfg.disable_g92_persistence);
	flag("RS274NGC", "DISABLE_FANUC_STYLE_SUB", cfg.disable_fanuc_style_sub);
	flag("RS274NGC", "INI_VARS", cfg.ini_vars);
	flag("RS274NGC", "HAL_PIN_VARS", cfg.hal_pin_vars);
	if (get("EMCIO", "TOOL_TABLE", v))
		cfg.tool_table = rel(v);
	flag("EMCIO", "RANDOM_TOOLCHANGER", cfg.random_toolchanger);
	flag("EMCIO", "TOOL_CHANGE_QUILL_UP", cfg.tool_change_quill_up);
	flag("EMCIO", "TOOL_CHANGE_AT_G30", cfg.tool_change_at_g30);
	flag("EMCIO", "TOOL_CHANGE_WITH_SPINDLE_ON", cfg.tool_change_with_spindle_on);
	return !bad;
}

}  // namespace rs274
