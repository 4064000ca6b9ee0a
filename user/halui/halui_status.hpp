// SPDX-License-Identifier: GPL-2.0-or-later
// halui_status.hpp - the part of task's status (docs/bus.md "Status keys") halui
// shows on its OUT pins and decides with, parsed once per cycle from the key/value
// block, so the logic (halui_core) works on numbers and unit tests can fill it in.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace hal::halui {

struct JointStatus {
    bool homed = false, fault = false;
    bool min_soft = false, max_soft = false, min_hard = false, max_hard = false;
    bool override_limits = false;
};

struct SpindleStatus {
    double speed = 0;      // motion's commanded speed (signed)
    double scale = 1;      // override
    int direction = 0;     // -1, 0, 1
    bool enabled = false, brake = false;
};

struct StatusView {
    std::string state = "ESTOP";      // task.state: ESTOP, ESTOP_RESET, ON
    std::string mode = "MANUAL";      // task.mode
    std::string interp = "IDLE";      // task.interp
    std::string traj_mode = "FREE";   // traj.mode
    std::string file;                 // task.file (empty: no program open)
    bool paused = false, optional_stop = false, block_delete = false;
    bool mist = false, flood = false, lube = false;
    double units_per_mm = 1;
    double feed_scale = 1, rapid_scale = 1, max_velocity = 0;
    double spindle_speed = 0;         // task.spindle_speed: the active S of spindle 0
    std::vector<JointStatus> joints;
    // per axis index (0 = x ... 8 = w); zero for axes that are not configured
    double pos_cmd[9] = {}, pos_fb[9] = {};
    double g5x[9] = {}, g92[9] = {}, tool_offset[9] = {};
    double rotation_xy = 0;           // degrees
    std::vector<SpindleStatus> spindles;
    int tool = 0;                     // io.tool_in_spindle
    double tool_diameter = 0;         // D of that tool in the table (0: none)
};

// Missing keys keep their defaults; malformed numbers read as 0.
StatusView parse_status(const std::map<std::string, std::string>& st, int joints, int spindles);

// The work position of axis a (halui.axis.L.pos-relative): feedback - G5x - tool
// offset, turned back by the XY rotation, - G92.
double relative_position(const StatusView& s, int a);

}  // namespace hal::halui
