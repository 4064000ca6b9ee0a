// SPDX-License-Identifier: GPL-2.0-or-later
// inihal_items.hpp - the `inihal` pins (motion.md 16.1): run-time overrides of INI
// values. Each item is one pin: its name and type, where its value lives in
// TaskConfig, and the motion commands that carry a change to motion. Pure: the HAL
// side (inihal.cpp, milltask) reads the pins and hands the values to inihal_apply().
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "task_config.hpp"

namespace hal::task {

enum class IniPinType { Float, S32, Bit };

struct IniItem {
    std::string name;   // "ini.0.max_velocity", "ini.x.min_limit", "ini.traj_max_velocity"
    IniPinType type;
    std::function<double(const TaskConfig&)> get;
    std::function<void(TaskConfig&, double)> set;
    // what motion is sent after a change (from the updated configuration); none for a
    // value only task uses
    std::function<std::vector<motion_command>(const TaskConfig&)> send;
};

// Every pin for this configuration: per joint, per axis in [TRAJ]COORDINATES, traj.
std::vector<IniItem> inihal_items(const TaskConfig& cfg);

// values[i] is the pin of items[i]. Values that differ from cfg are stored in it; the
// commands for them are returned in item order, each command once (both limits of a
// joint changed: one SET_JOINT_POSITION_LIMITS).
std::vector<motion_command> inihal_apply(const std::vector<IniItem>& items, const std::vector<double>& values,
                                         TaskConfig& cfg);

}  // namespace hal::task
