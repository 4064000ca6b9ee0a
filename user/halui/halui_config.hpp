// SPDX-License-Identifier: GPL-2.0-or-later
// halui_config.hpp - what halui reads from the INI file (emcrsh-and-halui.md 3.1):
// the machine's shape (joints, axes, spindles) that decides which pins exist, the
// override and velocity clamps, and the [HALUI]MDI_COMMAND lines.
#pragma once

#include <string>
#include <vector>

#include "hal/result.hpp"
#include "ini/axes.hpp"
#include "ini/ini_file.hpp"

namespace hal::halui {

constexpr int MAX_JOINTS = 16;       // motion's limit (motion_if.h)
constexpr int MAX_SPINDLES = 8;
constexpr int MAX_MDI_COMMANDS = 64; // halui.mdi-command-00 .. -63

struct Config {
    int joints = 3;                      // [KINS]JOINTS (default: one per coordinate letter)
    std::vector<int> axes;               // configured axis indices (0 = x ... 8 = w), ascending
    int spindles = 1;                    // [TRAJ]SPINDLES
    double max_feed_override = 1.0;      // [DISPLAY]MAX_FEED_OVERRIDE
    double min_spindle_override = 0.0;   // [DISPLAY]MIN_SPINDLE_OVERRIDE
    double max_spindle_override = 1.0;   // [DISPLAY]MAX_SPINDLE_OVERRIDE
    double max_velocity = 1.0;           // [TRAJ]MAX_LINEAR_VELOCITY, else [AXIS_X]MAX_VELOCITY
    std::vector<std::string> mdi;        // [HALUI]MDI_COMMAND in file order
};

// Errors name the file and line: "sim.ini:12: [HALUI]MDI_COMMAND: more than 64 commands".
Result<Config> read_config(const ini::IniFile& ini);

}  // namespace hal::halui
