// SPDX-License-Identifier: GPL-2.0-or-later
// task_state.cpp - state, mode and command rules (see task_state.hpp).
#include "task_state.hpp"

#include <cctype>
#include <set>

namespace hal::task {

const char* state_name(TaskState s)
{
    switch (s) {
    case TaskState::ESTOP: return "ESTOP";
    case TaskState::ESTOP_RESET: return "ESTOP_RESET";
    case TaskState::OFF: return "OFF";
    case TaskState::ON: return "ON";
    }
    return "?";
}

const char* mode_name(TaskMode m)
{
    switch (m) {
    case TaskMode::MANUAL: return "MANUAL";
    case TaskMode::AUTO: return "AUTO";
    case TaskMode::MDI: return "MDI";
    }
    return "?";
}

const char* interp_name(InterpState s)
{
    switch (s) {
    case InterpState::IDLE: return "IDLE";
    case InterpState::READING: return "READING";
    case InterpState::PAUSED: return "PAUSED";
    case InterpState::WAITING: return "WAITING";
    }
    return "?";
}

static std::string upper(const std::string& s)
{
    std::string r = s;
    for (char& c : r)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return r;
}

std::optional<TaskState> parse_state(const std::string& s)
{
    for (TaskState t : {TaskState::ESTOP, TaskState::ESTOP_RESET, TaskState::OFF, TaskState::ON})
        if (upper(s) == state_name(t))
            return t;
    return std::nullopt;
}

std::optional<TaskMode> parse_mode(const std::string& s)
{
    for (TaskMode m : {TaskMode::MANUAL, TaskMode::AUTO, TaskMode::MDI})
        if (upper(s) == mode_name(m))
            return m;
    return std::nullopt;
}

TaskState determine_state(bool io_estop, bool traj_enabled)
{
    if (io_estop)
        return TaskState::ESTOP;
    return traj_enabled ? TaskState::ON : TaskState::ESTOP_RESET;
}

std::string check_state_request(TaskState requested, TaskState current, bool io_ok, bool io_estop)
{
    switch (requested) {
    case TaskState::ESTOP:
    case TaskState::OFF:
        return "";   // always possible: the safe direction
    case TaskState::ESTOP_RESET:
        if (!io_ok)
            return "cannot reset estop: iocontrol is not connected";
        return "";
    case TaskState::ON:
        if (!io_ok)
            return "cannot turn the machine on: iocontrol is not connected";
        if (io_estop || current == TaskState::ESTOP)
            return "cannot turn the machine on while in estop (reset estop first)";
        return "";
    }
    return "unknown state";
}

std::string check_mode_change(TaskMode current, TaskMode requested, InterpState interp, bool jogging)
{
    if (current == requested)
        return "";
    if (jogging)
        return "Ignoring task mode change while jogging";
    if (current == TaskMode::AUTO && interp != InterpState::IDLE)
        return "Can't switch mode while mode is AUTO and interpreter is not IDLE";
    return "";
}

std::string check_command(const std::string& verb, const Situation& s)
{
    // commands that always pass: queries, state, overrides, abort, switches
    static const std::set<std::string> free_cmds = {
        "PING", "STATUS", "STATE", "ABORT", "FEED_OVERRIDE", "RAPID_OVERRIDE", "SPINDLE_OVERRIDE",
        "MAX_VELOCITY", "OPTIONAL_STOP", "BLOCK_DELETE", "DEBUG", "PROBE_CLEAR", "MODE", "TELEOP"};
    if (free_cmds.count(verb))
        return "";
    if (s.busy && (verb == "MDI" || verb == "RUN" || verb == "STEP" || verb == "OPEN" || verb == "CLOSE" ||
                   verb == "PLAN_INIT" || verb == "LOAD_TOOL_TABLE"))
        return verb + ": task is busy (waiting for motion in an interpreter call)";
    const bool on = s.state == TaskState::ON;
    const bool idle = s.interp == InterpState::IDLE;
    const std::string homing_hint = " (home all joints, or set [TRAJ]NO_FORCE_HOMING = 1)";
    if (verb == "MDI") {
        if (!on)
            return "MDI: machine is not on";
        if (s.mode != TaskMode::MDI)
            return "MDI: task is not in MDI mode";
        if (!s.all_homed && !s.no_force_homing)
            return "MDI: machine is not homed" + homing_hint;
        return "";
    }
    if (verb == "RUN" || verb == "STEP") {
        if (s.mode != TaskMode::AUTO)
            return verb + ": task is not in AUTO mode";
        if (!on)
            return verb + ": machine is not on";
        if (!s.program_open)
            return verb + ": no program is open";
        if (!s.all_homed && !s.no_force_homing)
            return verb + ": machine is not homed" + homing_hint;
        if (verb == "RUN" && !idle)
            return "RUN: a program is already running";
        return "";
    }
    if (verb == "OPEN" || verb == "CLOSE" || verb == "PLAN_INIT") {
        if (!idle)
            return verb + ": the interpreter is not idle";
        return "";
    }
    if (verb == "PAUSE" || verb == "RESUME") {
        if (s.mode == TaskMode::MANUAL)
            return verb + ": task is in MANUAL mode";
        return "";
    }
    if (verb == "HOME" || verb == "UNHOME" || verb == "JOG_CONT" || verb == "JOG_INCR" || verb == "JOG_ABS" ||
        verb == "JOG_STOP" || verb == "OVERRIDE_LIMITS") {
        if (s.mode != TaskMode::MANUAL)
            return verb + ": task is not in MANUAL mode";
        if (!on && verb != "JOG_STOP" && verb != "UNHOME")
            return verb + ": machine is not on";
        return "";
    }
    if (verb == "SPINDLE" || verb == "BRAKE") {
        if (!on)
            return verb + ": machine is not on";
        if (s.mode == TaskMode::AUTO && !idle)
            return verb + ": a program is running";
        return "";
    }
    if (verb == "MIST" || verb == "FLOOD" || verb == "LUBE") {
        if (s.state == TaskState::ESTOP)
            return verb + ": machine is in estop";
        return "";
    }
    if (verb == "TOOL_OFFSET" || verb == "LOAD_TOOL_TABLE") {
        if (!idle)
            return verb + ": the interpreter is not idle";
        return "";
    }
    return verb + ": unknown command";
}

}  // namespace hal::task
