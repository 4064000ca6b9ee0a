// SPDX-License-Identifier: GPL-2.0-or-later
// print_canon.hpp - a Canon that prints every call, one per line (rs274(1), tests):
//   <line> NAME(arg, arg, ...)
// <line> is the program line the call came from (0: interpreter init). Numbers are
// printed with 4 decimals (-0.0000 printed as 0.0000); positions list the configured
// axes only, in X Y Z A B C U V W order. No machine: a probe reports the target point,
// not tripped; M66 reads 0; user M codes are printed, not run (status 0).
#pragma once
#include <ostream>
#include <string>

#include "rs274/canon.hpp"

namespace rs274 {

class PrintCanon : public Canon {
public:
	PrintCanon(std::ostream& out, const std::string& axes);

	void block_begin(const std::string& file, int line) override;
	void use_length_units(Units u) override;
	void select_plane(Plane p) override;
	void set_g5x_offset(int index, const Pos& offset) override;
	void set_xy_rotation(double degrees) override;
	void set_g92_offset(const Pos& offset) override;
	void use_tool_length_offset(const Pos& offset) override;
	void set_motion_control_mode(MotionControl m, double tolerance) override;
	void set_naivecam_tolerance(double tolerance) override;
	void set_feed_mode(int spindle, FeedMode m) override;
	void set_feed_rate(double rate) override;
	void straight_traverse(const Pos& end) override;
	void straight_feed(const Pos& end) override;
	void arc_feed(double first_end, double second_end, double first_center, double second_center,
	              int rotation, const Pos& end) override;
	void straight_probe(const Pos& end, ProbeType type) override;
	ProbeResult probe_result() override;
	void rigid_tap(const Pos& end, double scale) override;
	void start_speed_feed_synch(int spindle, double feed_per_rev, bool velocity_mode) override;
	void stop_speed_feed_synch() override;
	void dwell(double seconds) override;
	void set_spindle_speed(int spindle, double rpm) override;
	void set_spindle_mode(int spindle, double css_factor, double max_rpm) override;
	void start_spindle_clockwise(int spindle) override;
	void start_spindle_counterclockwise(int spindle) override;
	void stop_spindle_turning(int spindle) override;
	void orient_spindle(int spindle, double degrees, int direction) override;
	void wait_spindle_orient_complete(int spindle, double timeout) override;
	void mist_on() override;
	void mist_off() override;
	void flood_on() override;
	void flood_off() override;
	void feed_override_enable(bool on) override;
	void speed_override_enable(int spindle, bool on) override;
	void adaptive_feed_enable(bool on) override;
	void feed_hold_enable(bool on) override;
	void select_tool(int tool) override;
	void change_tool(int tool) override;
	void change_tool_number(int tool) override;
	void set_tool_table_entry(int tool, int pocket, const Pos& offset, double diameter,
	                          double frontangle, double backangle, int orientation) override;
	void reload_tool_table() override;
	void set_motion_output_bit(int index, bool on) override;
	void set_aux_output_bit(int index, bool on) override;
	void set_motion_output_value(int index, double value) override;
	void set_aux_output_value(int index, double value) override;
	double wait_input(int index, bool analog, WaitType type, double timeout) override;
	void comment(const std::string& text) override;
	void message(const std::string& text) override;
	void print_text(const std::string& text) override;
	void program_stop() override;
	void optional_program_stop() override;
	void pallet_shuttle() override;
	void program_end() override;
	int user_m_code(int code, const std::string& path, double p, double q) override;
	bool hal_value(const std::string& name, double& value) override;

private:
	void emit(const std::string& call);
	std::string pos(const Pos& p) const;
	std::ostream& out_;
	bool axis_on_[NUM_AXES] = {};
	int line_ = 0;
	Pos last_probe_{};
};

// "%.4f" without negative zero.
std::string num(double v);

}  // namespace rs274
