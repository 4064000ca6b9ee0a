// SPDX-License-Identifier: GPL-2.0-or-later
// hold_canon.hpp - the canon the interpreter talks to: it forwards every call to the
// machine's canon, except while cutter radius compensation holds a move back (its end
// point depends on the next move, gcode.md 11.3). Then the calls made after the held
// move are queued so that they reach the machine after it, in program order; comp.cpp
// releases them once the held move has been emitted. Moves without motion in the
// compensation plane (Z plunges) are queued as positions, because their plane
// coordinates are those of the held move's final end point, known only later.
// Calls that read the machine (probe result, M66 input, user M code status, HAL
// values) cannot wait and go through at once.
#pragma once
#include <functional>
#include <utility>
#include <vector>

#include "rs274/canon.hpp"

namespace rs274 {

class HoldCanon : public Canon {
public:
	explicit HoldCanon(Canon& out) : out_(out) {}

	struct Item {
		std::function<void(Canon&)> call;   // a queued canon call, or
		bool move = false;                  // a plane-less move to this program position
		bool feed = false;
		Pos prog{};
	};
	Canon& machine() { return out_; }
	bool holding() const { return hold_; }
	void hold(bool on) { hold_ = on; }
	std::vector<Item> take() { std::vector<Item> q; q.swap(q_); return q; }
	void queue_move(const Pos& prog, bool feed)
	{
		limit();
		q_.push_back(Item{nullptr, true, feed, prog});
	}
	void drop() { q_.clear(); hold_ = false; }

	void block_begin(const std::string& f, int l) override { put([=](Canon& c) { c.block_begin(f, l); }); }
	void use_length_units(Units u) override { put([=](Canon& c) { c.use_length_units(u); }); }
	void select_plane(Plane p) override { put([=](Canon& c) { c.select_plane(p); }); }
	void set_g5x_offset(int i, const Pos& o) override { put([=](Canon& c) { c.set_g5x_offset(i, o); }); }
	void set_xy_rotation(double d) override { put([=](Canon& c) { c.set_xy_rotation(d); }); }
	void set_g92_offset(const Pos& o) override { put([=](Canon& c) { c.set_g92_offset(o); }); }
	void use_tool_length_offset(const Pos& o) override { put([=](Canon& c) { c.use_tool_length_offset(o); }); }
	void set_motion_control_mode(MotionControl m, double t) override { put([=](Canon& c) { c.set_motion_control_mode(m, t); }); }
	void set_naivecam_tolerance(double t) override { put([=](Canon& c) { c.set_naivecam_tolerance(t); }); }
	void set_feed_mode(int s, FeedMode m) override { put([=](Canon& c) { c.set_feed_mode(s, m); }); }
	void set_feed_rate(double r) override { put([=](Canon& c) { c.set_feed_rate(r); }); }
	void straight_traverse(const Pos& e) override { put([=](Canon& c) { c.straight_traverse(e); }); }
	void straight_feed(const Pos& e) override { put([=](Canon& c) { c.straight_feed(e); }); }
	void arc_feed(double fe, double se, double fc, double sc, int rot, const Pos& e) override
	{
		put([=](Canon& c) { c.arc_feed(fe, se, fc, sc, rot, e); });
	}
	void straight_probe(const Pos& e, ProbeType t) override { put([=](Canon& c) { c.straight_probe(e, t); }); }
	ProbeResult probe_result() override { return out_.probe_result(); }
	void rigid_tap(const Pos& e, double s) override { put([=](Canon& c) { c.rigid_tap(e, s); }); }
	void start_speed_feed_synch(int s, double f, bool v) override { put([=](Canon& c) { c.start_speed_feed_synch(s, f, v); }); }
	void stop_speed_feed_synch() override { put([](Canon& c) { c.stop_speed_feed_synch(); }); }
	void dwell(double s) override { put([=](Canon& c) { c.dwell(s); }); }
	void set_spindle_speed(int s, double r) override { put([=](Canon& c) { c.set_spindle_speed(s, r); }); }
	void set_spindle_mode(int s, double f, double m) override { put([=](Canon& c) { c.set_spindle_mode(s, f, m); }); }
	void start_spindle_clockwise(int s) override { put([=](Canon& c) { c.start_spindle_clockwise(s); }); }
	void start_spindle_counterclockwise(int s) override { put([=](Canon& c) { c.start_spindle_counterclockwise(s); }); }
	void stop_spindle_turning(int s) override { put([=](Canon& c) { c.stop_spindle_turning(s); }); }
	void orient_spindle(int s, double d, int dir) override { put([=](Canon& c) { c.orient_spindle(s, d, dir); }); }
	void wait_spindle_orient_complete(int s, double t) override { put([=](Canon& c) { c.wait_spindle_orient_complete(s, t); }); }
	void mist_on() override { put([](Canon& c) { c.mist_on(); }); }
	void mist_off() override { put([](Canon& c) { c.mist_off(); }); }
	void flood_on() override { put([](Canon& c) { c.flood_on(); }); }
	void flood_off() override { put([](Canon& c) { c.flood_off(); }); }
	void feed_override_enable(bool on) override { put([=](Canon& c) { c.feed_override_enable(on); }); }
	void speed_override_enable(int s, bool on) override { put([=](Canon& c) { c.speed_override_enable(s, on); }); }
	void adaptive_feed_enable(bool on) override { put([=](Canon& c) { c.adaptive_feed_enable(on); }); }
	void feed_hold_enable(bool on) override { put([=](Canon& c) { c.feed_hold_enable(on); }); }
	void select_tool(int t) override { put([=](Canon& c) { c.select_tool(t); }); }
	void change_tool(int t) override { put([=](Canon& c) { c.change_tool(t); }); }
	void change_tool_number(int t) override { put([=](Canon& c) { c.change_tool_number(t); }); }
	void set_tool_table_entry(int t, int p, const Pos& o, double d, double fa, double ba, int ori) override
	{
		put([=](Canon& c) { c.set_tool_table_entry(t, p, o, d, fa, ba, ori); });
	}
	void reload_tool_table() override { put([](Canon& c) { c.reload_tool_table(); }); }
	void set_motion_output_bit(int i, bool on) override { put([=](Canon& c) { c.set_motion_output_bit(i, on); }); }
	void set_aux_output_bit(int i, bool on) override { put([=](Canon& c) { c.set_aux_output_bit(i, on); }); }
	void set_motion_output_value(int i, double v) override { put([=](Canon& c) { c.set_motion_output_value(i, v); }); }
	void set_aux_output_value(int i, double v) override { put([=](Canon& c) { c.set_aux_output_value(i, v); }); }
	double wait_input(int i, bool a, WaitType t, double to) override { return out_.wait_input(i, a, t, to); }
	void comment(const std::string& t) override { put([=](Canon& c) { c.comment(t); }); }
	void message(const std::string& t) override { put([=](Canon& c) { c.message(t); }); }
	void print_text(const std::string& t) override { put([=](Canon& c) { c.print_text(t); }); }
	void program_stop() override { put([](Canon& c) { c.program_stop(); }); }
	void optional_program_stop() override { put([](Canon& c) { c.optional_program_stop(); }); }
	void pallet_shuttle() override { put([](Canon& c) { c.pallet_shuttle(); }); }
	void program_end() override { put([](Canon& c) { c.program_end(); }); }
	int user_m_code(int code, const std::string& path, double p, double q) override
	{
		return out_.user_m_code(code, path, p, q);
	}
	bool hal_value(const std::string& n, double& v) override { return out_.hal_value(n, v); }

private:
	// Bounded memory: a loop that makes calls forever behind a held move is an error.
	static constexpr size_t MAX_HELD = 10000;
	void limit() const
	{
		if (q_.size() >= MAX_HELD)
			fail("More than %zu calls between two moves with cutter radius compensation on", MAX_HELD);
	}
	// A template so that forwarding (the common case) makes no std::function.
	template <class F>
	void put(F&& f)
	{
		if (hold_) {
			limit();
			q_.push_back(Item{std::function<void(Canon&)>(std::forward<F>(f)), false, false, {}});
		} else {
			f(out_);
		}
	}
	Canon& out_;
	bool hold_ = false;
	std::vector<Item> q_;
};

}  // namespace rs274
