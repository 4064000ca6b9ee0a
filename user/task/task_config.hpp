// SPDX-License-Identifier: GPL-2.0-or-later
// task_config.hpp - what task reads from the INI file ([TASK], [EMCMOT], [TRAJ],
// [KINS], [AXIS_L], [JOINT_n], [SPINDLE_n], [DISPLAY]) and the motion commands it
// sends at start (motion.md 16.2). Pure: unit tests check both without a machine.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "hal/result.hpp"
#include "ini/axes.hpp"
#include "ini/ini_file.hpp"
#include "motion_if.h"

namespace hal::task {

struct JointConfig {
    int type = 1;                  // 1 LINEAR, 2 ANGULAR
    double max_vel = 1.0, max_acc = 1.0;
    double min_limit = -1e99, max_limit = 1e99;
    double backlash = 0, ferror = 1.0, min_ferror = 1.0;
    double home = 0, home_offset = 0, home_search_vel = 0, home_latch_vel = 0, home_final_vel = -1;
    int home_flags = 0;            // HOME_* bits of kernel/motion/homing/homing.h
    int home_sequence = 999;
    bool volatile_home = false;
    std::string comp_file;
    int comp_file_type = 0;
};

struct AxisConfig {
    bool present = false;          // letter in [TRAJ]COORDINATES
    double max_vel = 1.0, max_acc = 1.0;
    double min_limit = -1e99, max_limit = 1e99;
    int locking_joint = -1;
};

struct SpindleConfig {
    double min_fwd = 0, max_fwd = 1e99, min_rev = 0, max_rev = 1e99, increment = 100;
};

struct TaskConfig {
    std::string ini_path;
    double cycle_time = 0.100;     // [TASK]CYCLE_TIME
    int interp_max_len = 1000;     // [TASK]INTERP_MAX_LEN
    int mdi_queued = 10;           // [TASK]MDI_QUEUED_COMMANDS
    double comm_timeout = 1.0;     // [EMCMOT]COMM_TIMEOUT
    std::string coordinates = "XYZ";
    int joints = 3;                // [KINS]JOINTS
    int spindles = 1;              // [TRAJ]SPINDLES
    std::string linear_units = "mm";
    double units_per_mm = 1.0;
    std::string angular_units = "deg";
    double default_vel = 1.0, max_vel = 1e99, default_acc = 1e99, max_acc = 1e99;
    double max_feed_override = 1.0;   // [DISPLAY]MAX_FEED_OVERRIDE
    bool no_force_homing = false;
    bool no_probe_jog_error = false, no_probe_home_error = false;
    std::string position_file;     // [TRAJ]POSITION_FILE (INI-relative)
    std::vector<double> motor_offset;   // per joint, from the position file at start (may be shorter)
    // [TRAJ]ARC_BLEND_ENABLE, _FALLBACK_ENABLE, _OPTIMIZATION_DEPTH, _GAP_CYCLES, _RAMP_FREQ, _KINK_RATIO
    // fallback on: this planner blends arc-line corners parabolically (docs/motion-tp.md)
    bool arc_blend_enable = true, arc_blend_fallback = true;
    int arc_blend_depth = 50;
    double arc_blend_gap_cycles = 4, arc_blend_ramp_freq = 100, arc_blend_kink_ratio = 0.1;
    std::array<double, MOTION_MAX_AXES> world_home{};
    std::array<AxisConfig, MOTION_MAX_AXES> axis;
    std::vector<JointConfig> joint;
    std::vector<SpindleConfig> spindle;
};

// Errors name the INI file and line ("FILE:LINE: [JOINT_0]MAX_VELOCITY: 'x' is not a number").
Result<TaskConfig> read_task_config(const ini::IniFile& ini);

// The start-up commands, in motion.md 16.2's order. A comp file that cannot be read
// is an error naming it.
Result<std::vector<motion_command>> motion_init_commands(const TaskConfig& cfg);

// One command from the configuration, as start-up sends it (and inihal after a
// change): joint_command for the SET_JOINT_* / UPDATE_JOINT_HOMING_PARAMS types,
// axis_command for SET_AXIS_POSITION/VEL/ACC_LIMIT, traj_command for SET_VEL,
// SET_VEL_LIMIT, SET_ACC, SETUP_ARC_BLENDS.
motion_command joint_command(const TaskConfig& cfg, int joint, int type);
motion_command axis_command(const TaskConfig& cfg, int axis, int type);
motion_command traj_command(const TaskConfig& cfg, int type);

using hal::ini::AXIS_LETTERS;

// A path from the INI file: absolute as given, else relative to the INI's directory.
std::string ini_relative(const std::string& ini_path, const std::string& file);

}  // namespace hal::task
