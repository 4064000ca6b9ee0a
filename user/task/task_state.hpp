// SPDX-License-Identifier: GPL-2.0-or-later
// task_state.hpp - task's states, modes and interpreter states (motion.md 16) and the
// rules for which command is accepted when. Pure functions: the unit tests drive them
// with every combination, task calls them before acting.
#pragma once

#include <optional>
#include <string>

namespace hal::task {

enum class TaskState { ESTOP = 1, ESTOP_RESET = 2, OFF = 3, ON = 4 };
enum class TaskMode { MANUAL = 1, AUTO = 2, MDI = 3 };
enum class InterpState { IDLE = 1, READING = 2, PAUSED = 3, WAITING = 4 };

const char* state_name(TaskState s);
const char* mode_name(TaskMode m);
const char* interp_name(InterpState s);
std::optional<TaskState> parse_state(const std::string& s);   // case-insensitive
std::optional<TaskMode> parse_mode(const std::string& s);

// The reported state (2.9 determineState): io estop -> ESTOP; motion not enabled ->
// ESTOP_RESET; else ON. OFF is only ever requested.
TaskState determine_state(bool io_estop, bool traj_enabled);

// Whether a state request may be carried out; "" when it may, else the refusal.
// io_ok: the io client is connected; io_estop: its estop input is active.
std::string check_state_request(TaskState requested, TaskState current, bool io_ok, bool io_estop);

// Mode change rules (2.9 emcTaskSetMode).
std::string check_mode_change(TaskMode current, TaskMode requested, InterpState interp, bool jogging);

struct Situation {
    TaskState state = TaskState::ESTOP;
    TaskMode mode = TaskMode::MANUAL;
    InterpState interp = InterpState::IDLE;
    bool all_homed = false;
    bool no_force_homing = false;
    bool program_open = false;
    bool busy = false;   // task is inside a blocking interpreter call (probe, M66): no new work
};

// The per-command preconditions (verb as the bus names it, docs/bus.md).
std::string check_command(const std::string& verb, const Situation& s);

}  // namespace hal::task
