// SPDX-License-Identifier: GPL-2.0-or-later
// task_canon.hpp - task's canon: the interpreter's canonical calls turned into a queue
// of work items (motion commands, io commands, waits, messages). No motion or HAL
// here: the unit tests call the canon and read the queue. The few calls that read
// the machine (probe result, M66, user M codes, HAL values) go to a Host, which
// first runs the queue to its end (docs/task.md "Synchronisation").
#pragma once

#include <array>
#include <deque>
#include <string>
#include <vector>

#include "motion_if.h"
#include "rs274/canon.hpp"
#include "task_config.hpp"

namespace hal::task {

struct Item {
    enum Kind {
        Motion,        // send cmd to motion (queued moves wait for room in motion's queue)
        Io,            // send io words to iocontrol, wait for its DONE
        Delay,         // G4: wait `seconds` after motion has stopped
        Message,       // operator message (kind, text)
        Stop,          // M0/M60: pause once everything before has finished
        OptionalStop,  // M1: same when optional stop is on
        End,           // M2/M30: the program is over once everything before has finished
    };
    Kind kind = Motion;
    int line = 0;                     // program line the call came from
    bool wait_motion = false;         // motion must have finished everything before
    motion_command cmd{};
    std::vector<std::string> io;
    double seconds = 0;
    std::string msg_kind, text;
};

class TaskCanon : public rs274::Canon {
public:
    struct Host {
        virtual ~Host() = default;
        // The queue is run to its end, motion stopped; then the probe's result.
        virtual rs274::ProbeResult probe_result() = 0;
        virtual double wait_input(int index, bool analog, rs274::WaitType type, double timeout) = 0;
        virtual int user_m_code(int code, const std::string& path, double p, double q) = 0;
        virtual bool hal_value(const std::string& name, double& value) = 0;
    };

    TaskCanon(const TaskConfig& cfg, Host& host) : cfg_(cfg), host_(host) {}

    std::deque<Item>& queue() { return queue_; }
    // Where the next move starts (machine coordinates): set when task re-synchs.
    void set_position(const rs274::Pos& p) { pos_ = p; }
    const rs274::Pos& position() const { return pos_; }
    // The interpreter's view, for status
    struct View {
        rs274::Units units = rs274::Units::MM;
        rs274::Plane plane = rs274::Plane::XY;
        rs274::FeedMode feed_mode = rs274::FeedMode::UNITS_PER_MINUTE;
        rs274::MotionControl motion_control = rs274::MotionControl::EXACT_PATH;
        double tolerance = 0;
        double feed = 0;
        std::array<double, MOTION_MAX_SPINDLES> speed{};
        int g5x_index = 1;
        rs274::Pos g5x{}, g92{}, tool_offset{};
        double rotation = 0;
        int selected_tool = -1;
        bool mist = false, flood = false;
        std::string file;
        int line = 0;
    };
    const View& view() const { return view_; }
    // Moves after this are tagged with the line; a skip-mode canon (RUN from a line)
    // keeps state reports but queues nothing.
    void set_skip(bool skip) { skip_ = skip; }

    // rs274::Canon
    void block_begin(const std::string& file, int line) override;
    void use_length_units(rs274::Units u) override { view_.units = u; }
    void select_plane(rs274::Plane p) override { view_.plane = p; }
    void set_g5x_offset(int index, const rs274::Pos& offset) override;
    void set_xy_rotation(double degrees) override { view_.rotation = degrees; }
    void set_g92_offset(const rs274::Pos& offset) override { view_.g92 = offset; }
    void use_tool_length_offset(const rs274::Pos& offset) override;
    void set_motion_control_mode(rs274::MotionControl m, double tolerance) override;
    void set_naivecam_tolerance(double) override {}
    void set_feed_mode(int spindle, rs274::FeedMode m) override;
    void set_feed_rate(double rate) override { view_.feed = rate; }
    void straight_traverse(const rs274::Pos& end) override;
    void straight_feed(const rs274::Pos& end) override;
    void arc_feed(double first_end, double second_end, double first_center, double second_center, int rotation,
                  const rs274::Pos& end) override;
    void straight_probe(const rs274::Pos& end, rs274::ProbeType type) override;
    rs274::ProbeResult probe_result() override;
    void rigid_tap(const rs274::Pos& end, double scale) override;
    void start_speed_feed_synch(int spindle, double feed_per_rev, bool velocity_mode) override;
    void stop_speed_feed_synch() override;
    void dwell(double seconds) override;
    void set_spindle_speed(int spindle, double rpm) override;
    void set_spindle_mode(int spindle, double css_factor, double max_rpm) override;
    void start_spindle_clockwise(int spindle) override { spindle_on(spindle, 1); }
    void start_spindle_counterclockwise(int spindle) override { spindle_on(spindle, -1); }
    void stop_spindle_turning(int spindle) override;
    void orient_spindle(int spindle, double degrees, int direction) override;
    void wait_spindle_orient_complete(int spindle, double timeout) override;
    void mist_on() override { io({"MIST", "1"}); view_.mist = true; }
    void mist_off() override { io({"MIST", "0"}); view_.mist = false; }
    void flood_on() override { io({"FLOOD", "1"}); view_.flood = true; }
    void flood_off() override { io({"FLOOD", "0"}); view_.flood = false; }
    void feed_override_enable(bool on) override { enable(MOTCMD_FS_ENABLE, on); }
    void speed_override_enable(int spindle, bool on) override;
    void adaptive_feed_enable(bool on) override { enable(MOTCMD_AF_ENABLE, on); }
    void feed_hold_enable(bool on) override { enable(MOTCMD_FH_ENABLE, on); }
    void select_tool(int tool) override;
    void change_tool(int tool) override;
    void change_tool_number(int tool) override;
    void set_tool_table_entry(int tool, int pocket, const rs274::Pos& offset, double diameter, double frontangle,
                              double backangle, int orientation) override;
    void reload_tool_table() override { io({"LOAD_TOOL_TABLE"}); }
    void set_motion_output_bit(int index, bool on) override;
    void set_aux_output_bit(int index, bool on) override;
    void set_motion_output_value(int index, double value) override;
    void set_aux_output_value(int index, double value) override;
    double wait_input(int index, bool analog, rs274::WaitType type, double timeout) override;
    void comment(const std::string&) override {}
    void message(const std::string& text) override { msg("DISPLAY", text); }
    void print_text(const std::string& text) override { msg("TEXT", text); }
    void program_stop() override { special(Item::Stop); }
    void optional_program_stop() override { special(Item::OptionalStop); }
    void pallet_shuttle() override {}
    void program_end() override { special(Item::End); }
    int user_m_code(int code, const std::string& path, double p, double q) override;
    bool hal_value(const std::string& name, double& value) override { return host_.hal_value(name, value); }

    // Velocity and acceleration limits of a straight move (machine units/s, /s^2):
    // each axis's [AXIS_L] limits scaled to the move's direction, capped by [TRAJ].
    void line_limits(const rs274::Pos& start, const rs274::Pos& end, double& vel, double& acc) const;

private:
    motion_command base(int type) const;
    void push(Item it);
    void push_cmd(const motion_command& c, bool wait_motion = false);   // a motion command item
    // a move's command: target, velocity, the limit feed override may reach, acceleration
    motion_command move_cmd(int type, int motion_type, const rs274::Pos& end, double vel, double ini_maxvel,
                            double acc) const;
    void move(int type, int motion_type, const rs274::Pos& end, double vel, double ini_maxvel, double acc);
    double feed_velocity(const rs274::Pos& start, const rs274::Pos& end, double vel_limit) const;
    void spindle_on(int spindle, int dir);
    void enable(int type, bool on);
    void io(std::vector<std::string> words, bool wait_motion = true);
    void msg(const std::string& kind, const std::string& text);
    void special(Item::Kind k);
    void output(bool analog, int index, double value, bool now);

    const TaskConfig& cfg_;
    Host& host_;
    std::deque<Item> queue_;
    rs274::Pos pos_{};
    View view_;
    bool skip_ = false;
    double css_factor_[MOTION_MAX_SPINDLES] = {};
    double css_max_[MOTION_MAX_SPINDLES] = {};
};

}  // namespace hal::task
