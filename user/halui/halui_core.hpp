// SPDX-License-Identifier: GPL-2.0-or-later
// halui_core.hpp - halui's logic without HAL or sockets: each cycle the IN pin values
// and task's status go in; the OUT pin values and the bus commands to send come out
// (emcrsh-and-halui.md 3.2). Commands are sent only on edges (and while a jog's speed
// changes); nothing here waits: the MDI_COMMAND sequence advances when the caller
// reports the bus's DONE/ERROR through on_result().
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "halui_config.hpp"
#include "halui_override.hpp"
#include "halui_status.hpp"

namespace hal::halui {

// The IN pins of one joint, one axis, or the selected joint/axis.
struct JogIn {
    bool select = false;
    bool home = false, unhome = false;          // joints only
    bool plus = false, minus = false;
    double analog = 0;                           // not on the selected ones
    double increment = 0;
    bool increment_plus = false, increment_minus = false;
};

struct SpindleIn {
    bool start = false, forward = false, reverse = false, stop = false;
    bool increase = false, decrease = false, brake_on = false, brake_off = false;
    OverrideIn override_;
};

// halui.mdi-command-NN (a struct so pins can point at it, unlike vector<bool>)
struct MdiIn {
    bool run = false;
};

struct Inputs {
    bool abort = false;
    bool machine_on = false, machine_off = false, estop_activate = false, estop_reset = false;
    bool mode_manual = false, mode_auto = false, mode_mdi = false, mode_teleop = false, mode_joint = false;
    bool mist_on = false, mist_off = false, flood_on = false, flood_off = false, lube_on = false, lube_off = false;
    bool program_run = false, program_pause = false, program_resume = false, program_step = false,
         program_stop = false;
    bool optional_stop_on = false, optional_stop_off = false, block_delete_on = false, block_delete_off = false;
    bool home_all = false;
    std::vector<JogIn> joint;                    // Config::joints
    JogIn joint_selected;
    double joint_jog_speed = 0, joint_jog_deadband = 0.2;   // units per minute
    std::vector<JogIn> axis;                     // Config::axes order
    JogIn axis_selected;
    double axis_jog_speed = 0, axis_jog_deadband = 0.2;
    std::vector<SpindleIn> spindle;              // Config::spindles
    OverrideIn feed, rapid, max_velocity;
    std::vector<MdiIn> mdi;                      // Config::mdi
};

struct JointOut {
    bool is_selected = false, is_homed = false, has_fault = false;
    bool on_soft_min = false, on_soft_max = false, on_hard_min = false, on_hard_max = false;
    bool override_limits = false;
};

struct AxisOut {
    bool is_selected = false;
    double pos_commanded = 0, pos_feedback = 0, pos_relative = 0;
};

struct SpindleOut {
    bool is_on = false, runs_forward = false, runs_backward = false, brake_is_on = false;
    double override_value = 1;
};

struct Outputs {
    bool machine_is_on = false, estop_is_activated = true;
    double units_per_mm = 1;
    bool is_manual = true, is_auto = false, is_mdi = false, is_teleop = false, is_joint = true;
    bool mist_is_on = false, flood_is_on = false, lube_is_on = false;
    bool program_is_idle = true, program_is_running = false, program_is_paused = false;
    bool optional_stop_is_on = false, block_delete_is_on = false;
    std::vector<JointOut> joint;
    JointOut joint_selected;
    unsigned joint_selected_index = 0;
    std::vector<AxisOut> axis;
    unsigned axis_selected_index = 0;            // axis number: 0 = x ... 8 = w
    std::vector<SpindleOut> spindle;
    double feed_value = 1, rapid_value = 1, max_velocity_value = 0;
    unsigned tool_number = 0;
    double tool_length_offset[9] = {};
    double tool_diameter = 0;
};

// A bus command line ("MODE MDI") and who wants its outcome (0: nobody but the log).
struct Command {
    std::string line;
    int tag = 0;
};

class Core {
public:
    explicit Core(Config cfg);

    // Sized inputs/outputs for this configuration (pins read into / written from them).
    Inputs make_inputs() const;
    Outputs make_outputs() const;

    // One cycle. 'st' null: no status (task not reachable): outputs kept, edges
    // remembered but nothing sent. Returns the commands to send, in order.
    std::vector<Command> cycle(const Inputs& in, const StatusView* st, double now_s, Outputs& out);
    // The outcome of a command that carried a tag (DONE: ok, else ERROR text).
    void on_result(int tag, bool ok);
    // Notes for the operator (stderr), oldest first.
    std::vector<std::string> take_notes();

    bool mdi_busy() const { return mdi_step_ != MdiStep::Idle; }
    const Config& config() const { return cfg_; }

private:
    enum class MdiStep { Idle, WaitMode, WaitMdi, WaitRestore };
    struct JogState {
        bool analog_jogging = false;
    };

    void write_outputs(const StatusView& st, Outputs& out) const;
    void simple_commands(const Inputs& in, const StatusView& st, std::vector<Command>& cmds);
    void jogs(const Inputs& in, std::vector<Command>& cmds);
    void jog_one(const std::string& target, const JogIn& cur, const JogIn& prev, double speed, bool speed_changed,
                 double deadband, JogState* analog, std::vector<Command>& cmds);
    void spindles(const Inputs& in, const StatusView& st, double now_s, std::vector<Command>& cmds);
    void overrides(const Inputs& in, const StatusView& st, double now_s, std::vector<Command>& cmds);
    void mdi_commands(const Inputs& in, const StatusView& st, std::vector<Command>& cmds);
    void mdi_advance(std::vector<Command>& cmds);

    Config cfg_;
    bool started_ = false;
    Inputs prev_;
    unsigned joint_selected_ = 0;
    size_t axis_selected_ = 0;                   // position in cfg_.axes
    std::vector<JogState> joint_jog_, axis_jog_;
    OverrideKnob feed_, rapid_, max_velocity_;
    std::vector<OverrideKnob> spindle_override_;
    // MDI_COMMAND sequence: requested indices wait their turn; the mode before the
    // first one is restored after the last (MANUAL or AUTO; MDI stays)
    std::vector<size_t> mdi_queue_;
    MdiStep mdi_step_ = MdiStep::Idle;
    std::string mdi_saved_mode_;
    std::string mode_now_ = "MANUAL";
    std::vector<Command> pending_;               // produced by on_result, sent next cycle
    std::vector<std::string> notes_;
};

// Tags of the MDI sequence's commands.
constexpr int TAG_MDI_MODE = 1, TAG_MDI_LINE = 2, TAG_MDI_RESTORE = 3;

}  // namespace hal::halui
