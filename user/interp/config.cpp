// SPDX-License-Identifier: GPL-2.0-or-later
// config.cpp - Config::from_ini: the [RS274NGC], [TRAJ], [DISPLAY] and [EMCIO] keys the
// interpreter uses (ini-and-launch.md 2.5). Relative paths are relative to the INI
// file's directory. Every key/value is also kept for #<_ini[section]key>.
#include <cctype>
#include <cstdlib>
#include <fstream>

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
	std::ifstream in(path);
	if (!in) {
		error = path + ": cannot open INI file";
		return false;
	}
	std::string dir = ".";
	size_t slash = path.rfind('/');
	if (slash != std::string::npos)
		dir = slash == 0 ? "/" : path.substr(0, slash);
	std::string line, section;
	int lineno = 0;
	while (std::getline(in, line)) {
		lineno++;
		std::string t = trim(line);
		if (t.empty() || t[0] == '#' || t[0] == ';')
			continue;
		if (t[0] == '[') {
			size_t e = t.find(']');
			if (e == std::string::npos) {
				error = path + ":" + std::to_string(lineno) + ": unterminated section name";
				return false;
			}
			section = upper(trim(t.substr(1, e - 1)));
			continue;
		}
		size_t eq = t.find('=');
		if (eq == std::string::npos)
			continue;
		std::string key = upper(trim(t.substr(0, eq)));
		std::string k = section + "]" + key;
		if (!cfg.ini.count(k))
			cfg.ini[k] = trim(t.substr(eq + 1));
	}
	auto get = [&](const char* sec, const char* key, std::string& v) {
		auto it = cfg.ini.find(std::string(sec) + "]" + key);
		if (it == cfg.ini.end())
			return false;
		v = it->second;
		return true;
	};
	auto rel = [&](const std::string& p) { return p.empty() || p[0] == '/' ? p : dir + "/" + p; };
	auto flag = [&](const char* sec, const char* key, bool& out) {
		std::string v;
		if (get(sec, key, v))
			out = std::atoi(v.c_str()) != 0;
	};
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
	if (get("TRAJ", "COORDINATES", v)) {
		cfg.axes.clear();
		for (char c : v)
			if (c != ' ' && c != '\t')
				cfg.axes += (char)std::toupper((unsigned char)c);
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
	if (get("RS274NGC", "ORIENT_OFFSET", v))
		cfg.orient_offset = std::atof(v.c_str());
	if (get("RS274NGC", "CENTER_ARC_RADIUS_TOLERANCE_INCH", v))
		cfg.center_arc_tolerance_inch = std::atof(v.c_str());
	if (get("RS274NGC", "CENTER_ARC_RADIUS_TOLERANCE_MM", v))
		cfg.center_arc_tolerance_mm = std::atof(v.c_str());
	flag("RS274NGC", "DISABLE_G92_PERSISTENCE", cfg.disable_g92_persistence);
	flag("RS274NGC", "INI_VARS", cfg.ini_vars);
	flag("RS274NGC", "HAL_PIN_VARS", cfg.hal_pin_vars);
	if (get("EMCIO", "TOOL_TABLE", v))
		cfg.tool_table = rel(v);
	flag("EMCIO", "RANDOM_TOOLCHANGER", cfg.random_toolchanger);
	flag("EMCIO", "TOOL_CHANGE_QUILL_UP", cfg.tool_change_quill_up);
	flag("EMCIO", "TOOL_CHANGE_AT_G30", cfg.tool_change_at_g30);
	flag("EMCIO", "TOOL_CHANGE_WITH_SPINDLE_ON", cfg.tool_change_with_spindle_on);
	return true;
}

}  // namespace rs274
