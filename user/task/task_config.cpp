// SPDX-License-Identifier: GPL-2.0-or-later
// task_config.cpp - INI keys -> TaskConfig -> motion start-up commands.
#include "task_config.hpp"

#include "ini/ini_reader.hpp"

#include "motcmd_parse.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

namespace hal::task {

std::string ini_relative(const std::string& ini_path, const std::string& file)
{
    if (file.empty() || file[0] == '/')
        return file;
    size_t slash = ini_path.rfind('/');
    return slash == std::string::npos ? file : ini_path.substr(0, slash + 1) + file;
}

namespace {

// linear units: mm, metric, inch, imperial (ini-and-launch.md 1.1) or a number of units per mm
bool linear_units(const std::string& s, double& per_mm, std::string& name)
{
    std::string l;
    for (char c : s)
        l += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (l == "mm" || l == "metric") {
        per_mm = 1.0;
        name = "mm";
    } else if (l == "inch" || l == "imperial" || l == "in") {
        per_mm = 1 / 25.4;
        name = "inch";
    } else if (l == "cm") {
        per_mm = 0.1;
        name = "cm";
    } else {
        return false;
    }
    return true;
}

}  // namespace

Result<TaskConfig> read_task_config(const ini::IniFile& ini)
{
    TaskConfig c;
    c.ini_path = ini.path();
    ini::Reader r{ini, {}};
    r.d("TASK", "CYCLE_TIME", c.cycle_time);
    r.i("TASK", "INTERP_MAX_LEN", c.interp_max_len);
    if (c.interp_max_len <= 0)
        c.interp_max_len = 1000;   // values <= 0 are ignored
    r.i("TASK", "MDI_QUEUED_COMMANDS", c.mdi_queued);
    if (c.mdi_queued <= 0)
        c.mdi_queued = 10;
    r.d("EMCMOT", "COMM_TIMEOUT", c.comm_timeout);
    r.coordinates(c.coordinates);
    if (!r.err.empty())
        return Error{-1, r.err};
    c.joints = static_cast<int>(c.coordinates.size());
    r.i("KINS", "JOINTS", c.joints);
    r.i("TRAJ", "SPINDLES", c.spindles);
    if (r.err.empty() && (c.joints < 1 || c.joints > MOTION_MAX_JOINTS))
        return Error{-1, ini.where("KINS", "JOINTS") + ": [KINS]JOINTS: " + std::to_string(c.joints) +
                             " out of range 1.." + std::to_string(MOTION_MAX_JOINTS)};
    if (r.err.empty() && (c.spindles < 0 || c.spindles > MOTION_MAX_SPINDLES))
        return Error{-1, ini.where("TRAJ", "SPINDLES") + ": [TRAJ]SPINDLES: " + std::to_string(c.spindles) +
                             " out of range 0.." + std::to_string(MOTION_MAX_SPINDLES)};
    if (auto v = ini.find("TRAJ", "LINEAR_UNITS"); v && !linear_units(*v, c.units_per_mm, c.linear_units))
        return Error{-1, ini.where("TRAJ", "LINEAR_UNITS") + ": [TRAJ]LINEAR_UNITS: '" + *v +
                             "' is not mm, metric, inch or imperial"};
    if (auto v = ini.find("TRAJ", "ANGULAR_UNITS"))
        c.angular_units = *v;
    r.d("TRAJ", "DEFAULT_LINEAR_VELOCITY", c.default_vel);
    r.d("TRAJ", "MAX_LINEAR_VELOCITY", c.max_vel);
    r.d("TRAJ", "DEFAULT_LINEAR_ACCELERATION", c.default_acc);
    r.d("TRAJ", "MAX_LINEAR_ACCELERATION", c.max_acc);
    r.b("TRAJ", "NO_FORCE_HOMING", c.no_force_homing);
    r.b("TRAJ", "NO_PROBE_JOG_ERROR", c.no_probe_jog_error);
    r.b("TRAJ", "NO_PROBE_HOME_ERROR", c.no_probe_home_error);
    r.d("DISPLAY", "MAX_FEED_OVERRIDE", c.max_feed_override);
    r.b("TRAJ", "ARC_BLEND_ENABLE", c.arc_blend_enable);
    r.b("TRAJ", "ARC_BLEND_FALLBACK_ENABLE", c.arc_blend_fallback);
    r.i("TRAJ", "ARC_BLEND_OPTIMIZATION_DEPTH", c.arc_blend_depth);
    r.d("TRAJ", "ARC_BLEND_GAP_CYCLES", c.arc_blend_gap_cycles);
    r.d("TRAJ", "ARC_BLEND_RAMP_FREQ", c.arc_blend_ramp_freq);
    r.d("TRAJ", "ARC_BLEND_KINK_RATIO", c.arc_blend_kink_ratio);
    c.position_file = ini_relative(c.ini_path, ini.find("TRAJ", "POSITION_FILE").value_or(""));
    if (auto v = ini.find("TRAJ", "HOME")) {
        std::istringstream in(*v);
        for (int k = 0; k < 3 && (in >> c.world_home[k]); ++k) {
        }
    }
    for (char letter : c.coordinates) {
        int a = ini::axis_index(letter);
        AxisConfig& ax = c.axis[a];
        ax.present = true;
        std::string sec = std::string("AXIS_") + AXIS_LETTERS[a];
        r.d(sec, "MAX_VELOCITY", ax.max_vel);
        r.d(sec, "MAX_ACCELERATION", ax.max_acc);
        r.d(sec, "MIN_LIMIT", ax.min_limit);
        r.d(sec, "MAX_LIMIT", ax.max_limit);
        r.i(sec, "LOCKING_INDEXER_JOINT", ax.locking_joint);
    }
    c.joint.resize(c.joints);
    for (int j = 0; j < c.joints; ++j) {
        JointConfig& jc = c.joint[j];
        std::string sec = "JOINT_" + std::to_string(j);
        if (auto t = ini.find(sec, "TYPE"); t && (*t == "ANGULAR" || *t == "angular"))
            jc.type = 2;
        r.d(sec, "MAX_VELOCITY", jc.max_vel);
        r.d(sec, "MAX_ACCELERATION", jc.max_acc);
        r.d(sec, "MIN_LIMIT", jc.min_limit);
        r.d(sec, "MAX_LIMIT", jc.max_limit);
        r.d(sec, "BACKLASH", jc.backlash);
        r.d(sec, "FERROR", jc.ferror);
        jc.min_ferror = jc.ferror;
        r.d(sec, "MIN_FERROR", jc.min_ferror);
        r.d(sec, "HOME", jc.home);
        r.d(sec, "HOME_OFFSET", jc.home_offset);
        r.d(sec, "HOME_SEARCH_VEL", jc.home_search_vel);
        r.d(sec, "HOME_LATCH_VEL", jc.home_latch_vel);
        r.d(sec, "HOME_FINAL_VEL", jc.home_final_vel);
        r.flag(sec, "HOME_IGNORE_LIMITS", 1, jc.home_flags);
        r.flag(sec, "HOME_USE_INDEX", 2, jc.home_flags);
        r.flag(sec, "HOME_IS_SHARED", 4, jc.home_flags);
        r.flag(sec, "LOCKING_INDEXER", 8, jc.home_flags);
        r.flag(sec, "HOME_INDEX_NO_ENCODER_RESET", 128, jc.home_flags);
        int abs_enc = 0;
        r.i(sec, "HOME_ABSOLUTE_ENCODER", abs_enc);
        if (abs_enc == 1)
            jc.home_flags |= 16;
        else if (abs_enc == 2)
            jc.home_flags |= 16 | 64;
        r.i(sec, "HOME_SEQUENCE", jc.home_sequence);
        r.b(sec, "VOLATILE_HOME", jc.volatile_home);
        jc.comp_file = ini_relative(c.ini_path, ini.find(sec, "COMP_FILE").value_or(""));
        r.i(sec, "COMP_FILE_TYPE", jc.comp_file_type);
    }
    c.spindle.resize(c.spindles);
    for (int s = 0; s < c.spindles; ++s) {
        SpindleConfig& sc = c.spindle[s];
        std::string sec = "SPINDLE_" + std::to_string(s);
        r.d(sec, "MAX_FORWARD_VELOCITY", sc.max_fwd);
        sc.max_rev = sc.max_fwd;
        r.d(sec, "MIN_FORWARD_VELOCITY", sc.min_fwd);
        sc.min_rev = sc.min_fwd;
        r.d(sec, "MAX_REVERSE_VELOCITY", sc.max_rev);
        r.d(sec, "MIN_REVERSE_VELOCITY", sc.min_rev);
        r.d(sec, "INCREMENT", sc.increment);
    }
    if (!r.err.empty())
        return Error{-1, r.err};
    return c;
}

static motion_command cmd(int type)
{
    motion_command c{};
    c.command = type;
    c.axis = -1;
    return c;
}

motion_command joint_command(const TaskConfig& cfg, int joint, int type)
{
    const JointConfig& jc = cfg.joint[joint];
    motion_command c = cmd(type);
    c.joint = joint;
    switch (type) {
    case MOTCMD_SET_JOINT_BACKLASH: c.value = jc.backlash; break;
    case MOTCMD_SET_JOINT_POSITION_LIMITS:
        c.minLimit = jc.min_limit;
        c.maxLimit = jc.max_limit;
        break;
    case MOTCMD_SET_JOINT_MAX_FERROR: c.value = jc.ferror; break;
    case MOTCMD_SET_JOINT_MIN_FERROR: c.value = jc.min_ferror; break;
    case MOTCMD_SET_JOINT_VEL_LIMIT: c.value = jc.max_vel; break;
    case MOTCMD_SET_JOINT_ACC_LIMIT: c.value = jc.max_acc; break;
    case MOTCMD_SET_JOINT_HOMING_PARAMS:
        c.home_final_vel = jc.home_final_vel;
        c.search_vel = jc.home_search_vel;
        c.latch_vel = jc.home_latch_vel;
        c.flags = jc.home_flags;
        c.volatile_home = jc.volatile_home ? 1 : 0;
        [[fallthrough]];
    case MOTCMD_UPDATE_JOINT_HOMING_PARAMS:
        c.offset = jc.home_offset;
        c.home = jc.home;
        c.home_sequence = jc.home_sequence;
        break;
    default: break;
    }
    return c;
}

motion_command axis_command(const TaskConfig& cfg, int axis, int type)
{
    const AxisConfig& ac = cfg.axis[axis];
    motion_command c = cmd(type);
    c.axis = axis;
    switch (type) {
    case MOTCMD_SET_AXIS_POSITION_LIMITS:
        c.minLimit = ac.min_limit;
        c.maxLimit = ac.max_limit;
        break;
    case MOTCMD_SET_AXIS_VEL_LIMIT: c.value = ac.max_vel; break;
    case MOTCMD_SET_AXIS_ACC_LIMIT: c.value = ac.max_acc; break;
    default: break;
    }
    return c;
}

motion_command traj_command(const TaskConfig& cfg, int type)
{
    motion_command c = cmd(type);
    switch (type) {
    case MOTCMD_SET_VEL:
        c.vel = cfg.default_vel;
        c.ini_maxvel = cfg.max_vel;
        break;
    case MOTCMD_SET_VEL_LIMIT: c.vel = cfg.max_vel; break;
    case MOTCMD_SET_ACC: c.acc = cfg.max_acc; break;
    case MOTCMD_SETUP_ARC_BLENDS:   // the fields of motion_if.h's SETUP_ARC_BLENDS
        c.mode = cfg.arc_blend_enable ? 1 : 0;
        c.flags = cfg.arc_blend_fallback ? 1 : 0;
        c.count = cfg.arc_blend_depth;
        c.value = cfg.arc_blend_gap_cycles;
        c.scale = cfg.arc_blend_ramp_freq;
        c.tolerance = cfg.arc_blend_kink_ratio;
        break;
    default: break;
    }
    return c;
}

Result<std::vector<motion_command>> motion_init_commands(const TaskConfig& cfg)
{
    std::vector<motion_command> out;
    motion_command c = cmd(MOTCMD_SET_NUM_JOINTS);
    c.count = cfg.joints;
    out.push_back(c);
    c = cmd(MOTCMD_SET_NUM_SPINDLES);
    c.count = cfg.spindles;
    out.push_back(c);
    for (int j = 0; j < cfg.joints; ++j) {
        const JointConfig& jc = cfg.joint[j];
        for (int type : {MOTCMD_SET_JOINT_BACKLASH, MOTCMD_SET_JOINT_POSITION_LIMITS, MOTCMD_SET_JOINT_MAX_FERROR,
                         MOTCMD_SET_JOINT_MIN_FERROR, MOTCMD_SET_JOINT_HOMING_PARAMS, MOTCMD_SET_JOINT_VEL_LIMIT,
                         MOTCMD_SET_JOINT_ACC_LIMIT})
            out.push_back(joint_command(cfg, j, type));
        if (!jc.comp_file.empty()) {
            std::ifstream f(jc.comp_file);
            if (!f)
                return Error{-1, "[JOINT_" + std::to_string(j) + "]COMP_FILE: cannot read " + jc.comp_file};
            std::string line;
            double n, fwd, rev;
            // motcmd's comp-file reader: reading stops at the first line that is not a point
            while (std::getline(f, line) && motcmd_comp_line(line, jc.comp_file_type, &n, &fwd, &rev)) {
                c = joint_command(cfg, j, MOTCMD_SET_JOINT_COMP);
                c.comp_nominal = n;
                c.comp_forward = fwd;
                c.comp_reverse = rev;
                out.push_back(c);
            }
        }
        out.push_back(joint_command(cfg, j, MOTCMD_JOINT_ACTIVATE));
        if (j < static_cast<int>(cfg.motor_offset.size())) {
            // [TRAJ]POSITION_FILE: the joint is where the file says (position_file.hpp)
            c = joint_command(cfg, j, MOTCMD_SET_JOINT_MOTOR_OFFSET);
            c.offset = cfg.motor_offset[j];
            out.push_back(c);
        }
    }
    for (int a = 0; a < MOTION_MAX_AXES; ++a) {
        const AxisConfig& ac = cfg.axis[a];
        if (!ac.present)
            continue;
        for (int type : {MOTCMD_SET_AXIS_POSITION_LIMITS, MOTCMD_SET_AXIS_VEL_LIMIT, MOTCMD_SET_AXIS_ACC_LIMIT})
            out.push_back(axis_command(cfg, a, type));
        if (ac.locking_joint >= 0) {
            c = axis_command(cfg, a, MOTCMD_SET_AXIS_LOCKING_JOINT);
            c.joint = ac.locking_joint;
            out.push_back(c);
        }
    }
    for (int s = 0; s < cfg.spindles; ++s) {
        const SpindleConfig& sc = cfg.spindle[s];
        c = cmd(MOTCMD_SET_SPINDLE_PARAMS);
        c.spindle = s;
        c.spindle_params[0] = sc.min_fwd;
        c.spindle_params[1] = sc.max_fwd;
        c.spindle_params[2] = sc.min_rev;
        c.spindle_params[3] = sc.max_rev;
        c.spindle_params[4] = sc.increment;
        out.push_back(c);
    }
    out.push_back(traj_command(cfg, MOTCMD_SET_VEL_LIMIT));
    out.push_back(traj_command(cfg, MOTCMD_SET_ACC));
    c = cmd(MOTCMD_SET_WORLD_HOME);
    for (int a = 0; a < MOTION_MAX_AXES; ++a)
        c.pos.v[a] = cfg.world_home[a];
    out.push_back(c);
    out.push_back(traj_command(cfg, MOTCMD_SETUP_ARC_BLENDS));
    c = cmd(MOTCMD_SET_MAX_FEED_OVERRIDE);
    c.scale = cfg.max_feed_override;
    out.push_back(c);
    c = cmd(MOTCMD_SET_PROBE_ERR_INHIBIT);
    c.mode = (cfg.no_probe_jog_error ? 1 : 0) | (cfg.no_probe_home_error ? 2 : 0);
    out.push_back(c);
    out.push_back(traj_command(cfg, MOTCMD_SET_VEL));
    return out;
}

}  // namespace hal::task
