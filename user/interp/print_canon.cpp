// SPDX-License-Identifier: GPL-2.0-or-later
// print_canon.cpp - the printing Canon of rs274(1) (format in print_canon.hpp).
#include "rs274/print_canon.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "ini/axes.hpp"

namespace rs274 {

std::string num(double v)
{
	char buf[64];
	std::snprintf(buf, sizeof buf, "%.4f", v);
	if (std::strcmp(buf, "-0.0000") == 0)
		return "0.0000";
	return buf;
}

PrintCanon::PrintCanon(std::ostream& out, const std::string& axes) : out_(out)
{
	for (char l : axes) {
		int a = hal::ini::axis_index(l);
		if (a >= 0)
			axis_on_[a] = true;
	}
}

void PrintCanon::emit(const std::string& call) { out_ << line_ << ' ' << call << '\n'; }

std::string PrintCanon::pos(const Pos& p) const
{
	std::string s;
	for (int a = 0; a < NUM_AXES; a++) {
		if (!axis_on_[a])
			continue;
		if (!s.empty())
			s += ", ";
		s += num(p[a]);
	}
	return s;
}

static std::string quote(const std::string& t) { return "\"" + t + "\""; }

void PrintCanon::block_begin(const std::string&, int line) { line_ = line; }
void PrintCanon::use_length_units(Units u) { emit(std::string("USE_LENGTH_UNITS(") + units_name(u) + ")"); }
void PrintCanon::select_plane(Plane p) { emit(std::string("SELECT_PLANE(") + plane_name(p) + ")"); }
void PrintCanon::set_g5x_offset(int index, const Pos& o)
{
	emit("SET_G5X_OFFSET(" + std::to_string(index) + ", " + pos(o) + ")");
}
void PrintCanon::set_xy_rotation(double d) { emit("SET_XY_ROTATION(" + num(d) + ")"); }
void PrintCanon::set_g92_offset(const Pos& o) { emit("SET_G92_OFFSET(" + pos(o) + ")"); }
void PrintCanon::use_tool_length_offset(const Pos& o) { emit("USE_TOOL_LENGTH_OFFSET(" + pos(o) + ")"); }
void PrintCanon::set_motion_control_mode(MotionControl m, double tol)
{
	emit(std::string("SET_MOTION_CONTROL_MODE(") + motion_control_name(m) + ", " + num(tol) + ")");
}
void PrintCanon::set_naivecam_tolerance(double tol) { emit("SET_NAIVECAM_TOLERANCE(" + num(tol) + ")"); }
void PrintCanon::set_feed_mode(int s, FeedMode m)
{
	emit("SET_FEED_MODE(" + std::to_string(s) + ", " + feed_mode_name(m) + ")");
}
void PrintCanon::set_feed_rate(double r) { emit("SET_FEED_RATE(" + num(r) + ")"); }
void PrintCanon::straight_traverse(const Pos& e) { emit("STRAIGHT_TRAVERSE(" + pos(e) + ")"); }
void PrintCanon::straight_feed(const Pos& e) { emit("STRAIGHT_FEED(" + pos(e) + ")"); }
void PrintCanon::arc_feed(double fe, double se, double fc, double sc, int rot, const Pos& e)
{
	emit("ARC_FEED(" + num(fe) + ", " + num(se) + ", " + num(fc) + ", " + num(sc) + ", " +
	     std::to_string(rot) + ", " + pos(e) + ")");
}
void PrintCanon::straight_probe(const Pos& e, ProbeType t)
{
	static const char* const names[] = {"G38.2", "G38.3", "G38.4", "G38.5"};
	last_probe_ = e;
	emit("STRAIGHT_PROBE(" + pos(e) + ", " + names[(int)t] + ")");
}
ProbeResult PrintCanon::probe_result() { return ProbeResult{last_probe_, false}; }
void PrintCanon::rigid_tap(const Pos& e, double scale) { emit("RIGID_TAP(" + pos(e) + ", " + num(scale) + ")"); }
void PrintCanon::start_speed_feed_synch(int s, double f, bool vel)
{
	emit("START_SPEED_FEED_SYNCH(" + std::to_string(s) + ", " + num(f) + ", " + (vel ? "1" : "0") + ")");
}
void PrintCanon::stop_speed_feed_synch() { emit("STOP_SPEED_FEED_SYNCH()"); }
void PrintCanon::dwell(double s) { emit("DWELL(" + num(s) + ")"); }
void PrintCanon::set_spindle_speed(int s, double r) { emit("SET_SPINDLE_SPEED(" + std::to_string(s) + ", " + num(r) + ")"); }
void PrintCanon::set_spindle_mode(int s, double k, double max)
{
	emit("SET_SPINDLE_MODE(" + std::to_string(s) + ", " + num(k) + ", " + (max >= 1e29 ? std::string("UNLIMITED") : num(max)) + ")");
}
void PrintCanon::start_spindle_clockwise(int s) { emit("START_SPINDLE_CLOCKWISE(" + std::to_string(s) + ")"); }
void PrintCanon::start_spindle_counterclockwise(int s) { emit("START_SPINDLE_COUNTERCLOCKWISE(" + std::to_string(s) + ")"); }
void PrintCanon::stop_spindle_turning(int s) { emit("STOP_SPINDLE_TURNING(" + std::to_string(s) + ")"); }
void PrintCanon::orient_spindle(int s, double d, int dir)
{
	emit("ORIENT_SPINDLE(" + std::to_string(s) + ", " + num(d) + ", " + std::to_string(dir) + ")");
}
void PrintCanon::wait_spindle_orient_complete(int s, double t)
{
	emit("WAIT_SPINDLE_ORIENT_COMPLETE(" + std::to_string(s) + ", " + num(t) + ")");
}
void PrintCanon::mist_on() { emit("MIST_ON()"); }
void PrintCanon::mist_off() { emit("MIST_OFF()"); }
void PrintCanon::flood_on() { emit("FLOOD_ON()"); }
void PrintCanon::flood_off() { emit("FLOOD_OFF()"); }
void PrintCanon::feed_override_enable(bool on) { emit(on ? "ENABLE_FEED_OVERRIDE()" : "DISABLE_FEED_OVERRIDE()"); }
void PrintCanon::speed_override_enable(int s, bool on)
{
	emit(std::string(on ? "ENABLE_SPEED_OVERRIDE(" : "DISABLE_SPEED_OVERRIDE(") + std::to_string(s) + ")");
}
void PrintCanon::adaptive_feed_enable(bool on) { emit(on ? "ENABLE_ADAPTIVE_FEED()" : "DISABLE_ADAPTIVE_FEED()"); }
void PrintCanon::feed_hold_enable(bool on) { emit(on ? "ENABLE_FEED_HOLD()" : "DISABLE_FEED_HOLD()"); }
void PrintCanon::select_tool(int t) { emit("SELECT_TOOL(" + std::to_string(t) + ")"); }
void PrintCanon::change_tool(int t) { emit("CHANGE_TOOL(" + std::to_string(t) + ")"); }
void PrintCanon::change_tool_number(int t) { emit("CHANGE_TOOL_NUMBER(" + std::to_string(t) + ")"); }
void PrintCanon::set_tool_table_entry(int tool, int pocket, const Pos& o, double d, double fa, double ba, int ori)
{
	std::string all;
	for (int a = 0; a < NUM_AXES; a++)
		all += num(o[a]) + ", ";
	emit("SET_TOOL_TABLE_ENTRY(" + std::to_string(tool) + ", " + std::to_string(pocket) + ", " + all +
	     num(d) + ", " + num(fa) + ", " + num(ba) + ", " + std::to_string(ori) + ")");
}
void PrintCanon::reload_tool_table() { emit("RELOAD_TOOL_TABLE()"); }
void PrintCanon::set_motion_output_bit(int i, bool on)
{
	emit(std::string(on ? "SET_MOTION_OUTPUT_BIT(" : "CLEAR_MOTION_OUTPUT_BIT(") + std::to_string(i) + ")");
}
void PrintCanon::set_aux_output_bit(int i, bool on)
{
	emit(std::string(on ? "SET_AUX_OUTPUT_BIT(" : "CLEAR_AUX_OUTPUT_BIT(") + std::to_string(i) + ")");
}
void PrintCanon::set_motion_output_value(int i, double v)
{
	emit("SET_MOTION_OUTPUT_VALUE(" + std::to_string(i) + ", " + num(v) + ")");
}
void PrintCanon::set_aux_output_value(int i, double v)
{
	emit("SET_AUX_OUTPUT_VALUE(" + std::to_string(i) + ", " + num(v) + ")");
}
double PrintCanon::wait_input(int i, bool analog, WaitType t, double timeout)
{
	emit("WAIT(" + std::to_string(i) + ", " + (analog ? "ANALOG" : "DIGITAL") + ", " +
	     std::to_string((int)t) + ", " + num(timeout) + ")");
	return 0;
}
void PrintCanon::comment(const std::string& t) { emit("COMMENT(" + quote(t) + ")"); }
void PrintCanon::message(const std::string& t) { emit("MESSAGE(" + quote(t) + ")"); }
void PrintCanon::print_text(const std::string& t) { emit("PRINT(" + quote(t) + ")"); }
void PrintCanon::program_stop() { emit("PROGRAM_STOP()"); }
void PrintCanon::optional_program_stop() { emit("OPTIONAL_PROGRAM_STOP()"); }
void PrintCanon::pallet_shuttle() { emit("PALLET_SHUTTLE()"); }
void PrintCanon::program_end() { emit("PROGRAM_END()"); }
int PrintCanon::user_m_code(int code, const std::string& path, double p, double q)
{
	emit("USER_M_CODE(" + std::to_string(code) + ", " + quote(path) + ", " + num(p) + ", " + num(q) + ")");
	return 0;
}
bool PrintCanon::hal_value(const std::string&, double&) { return false; }

}  // namespace rs274
