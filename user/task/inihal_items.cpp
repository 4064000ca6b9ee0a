// SPDX-License-Identifier: GPL-2.0-or-later
// inihal_items.cpp - the inihal pins and what a change sends (see inihal_items.hpp).
// Joint and axis values go to motion with the command start-up uses for them (both
// limits in one SET_*_POSITION_LIMITS; home, home_offset and home_sequence with
// UPDATE_JOINT_HOMING_PARAMS, motion.md 7); traj: default velocity SET_VEL, max
// velocity SET_VEL_LIMIT, max acceleration SET_ACC, the arc-blend values
// SETUP_ARC_BLENDS. The default acceleration is task's own (no command).
#include "inihal_items.hpp"

#include <cmath>
#include <set>
#include <tuple>
#include <type_traits>

namespace hal::task {

namespace {

using Cmds = std::vector<motion_command>;

// a double member of JointConfig / AxisConfig / TaskConfig as get/set
template <typename M>
IniItem joint_item(int j, const char* key, M JointConfig::*field, int command, IniPinType type = IniPinType::Float)
{
    return {"ini." + std::to_string(j) + "." + key, type,
            [j, field](const TaskConfig& c) { return static_cast<double>(c.joint[j].*field); },
            [j, field](TaskConfig& c, double v) { c.joint[j].*field = static_cast<M>(v); },
            [j, command](const TaskConfig& c) { return Cmds{joint_command(c, j, command)}; }};
}

IniItem axis_item(int a, const char* key, double AxisConfig::*field, int command)
{
    std::string letter(1, ini::axis_lower(a));
    return {"ini." + letter + "." + key, IniPinType::Float,
            [a, field](const TaskConfig& c) { return c.axis[a].*field; },
            [a, field](TaskConfig& c, double v) { c.axis[a].*field = v; },
            [a, command](const TaskConfig& c) { return Cmds{axis_command(c, a, command)}; }};
}

template <typename M>
IniItem traj_item(const char* key, M TaskConfig::*field, int command, IniPinType type = IniPinType::Float)
{
    return {std::string("ini.") + key, type, [field](const TaskConfig& c) { return static_cast<double>(c.*field); },
            [field](TaskConfig& c, double v) {
                if constexpr (std::is_same_v<M, bool>)
                    c.*field = v != 0;
                else
                    c.*field = static_cast<M>(v);
            },
            [command](const TaskConfig& c) { return command ? Cmds{traj_command(c, command)} : Cmds{}; }};
}

}  // namespace

std::vector<IniItem> inihal_items(const TaskConfig& cfg)
{
    std::vector<IniItem> out;
    for (int j = 0; j < cfg.joints; ++j) {
        out.push_back(joint_item(j, "backlash", &JointConfig::backlash, MOTCMD_SET_JOINT_BACKLASH));
        out.push_back(joint_item(j, "ferror", &JointConfig::ferror, MOTCMD_SET_JOINT_MAX_FERROR));
        out.push_back(joint_item(j, "min_ferror", &JointConfig::min_ferror, MOTCMD_SET_JOINT_MIN_FERROR));
        out.push_back(joint_item(j, "min_limit", &JointConfig::min_limit, MOTCMD_SET_JOINT_POSITION_LIMITS));
        out.push_back(joint_item(j, "max_limit", &JointConfig::max_limit, MOTCMD_SET_JOINT_POSITION_LIMITS));
        out.push_back(joint_item(j, "max_velocity", &JointConfig::max_vel, MOTCMD_SET_JOINT_VEL_LIMIT));
        out.push_back(joint_item(j, "max_acceleration", &JointConfig::max_acc, MOTCMD_SET_JOINT_ACC_LIMIT));
        out.push_back(joint_item(j, "home", &JointConfig::home, MOTCMD_UPDATE_JOINT_HOMING_PARAMS));
        out.push_back(joint_item(j, "home_offset", &JointConfig::home_offset, MOTCMD_UPDATE_JOINT_HOMING_PARAMS));
        out.push_back(joint_item(j, "home_sequence", &JointConfig::home_sequence, MOTCMD_UPDATE_JOINT_HOMING_PARAMS,
                                 IniPinType::S32));
    }
    for (int a = 0; a < MOTION_MAX_AXES; ++a) {
        if (!cfg.axis[a].present)
            continue;
        out.push_back(axis_item(a, "min_limit", &AxisConfig::min_limit, MOTCMD_SET_AXIS_POSITION_LIMITS));
        out.push_back(axis_item(a, "max_limit", &AxisConfig::max_limit, MOTCMD_SET_AXIS_POSITION_LIMITS));
        out.push_back(axis_item(a, "max_velocity", &AxisConfig::max_vel, MOTCMD_SET_AXIS_VEL_LIMIT));
        out.push_back(axis_item(a, "max_acceleration", &AxisConfig::max_acc, MOTCMD_SET_AXIS_ACC_LIMIT));
    }
    // the max velocity also rides on SET_VEL (ini_maxvel)
    out.push_back(traj_item("traj_default_velocity", &TaskConfig::default_vel, MOTCMD_SET_VEL));
    IniItem maxvel = traj_item("traj_max_velocity", &TaskConfig::max_vel, MOTCMD_SET_VEL_LIMIT);
    maxvel.send = [](const TaskConfig& c) {
        return Cmds{traj_command(c, MOTCMD_SET_VEL_LIMIT), traj_command(c, MOTCMD_SET_VEL)};
    };
    out.push_back(maxvel);
    out.push_back(traj_item("traj_default_acceleration", &TaskConfig::default_acc, 0));
    out.push_back(traj_item("traj_max_acceleration", &TaskConfig::max_acc, MOTCMD_SET_ACC));
    out.push_back(traj_item("traj_arc_blend_enable", &TaskConfig::arc_blend_enable, MOTCMD_SETUP_ARC_BLENDS,
                            IniPinType::Bit));
    out.push_back(traj_item("traj_arc_blend_fallback_enable", &TaskConfig::arc_blend_fallback,
                            MOTCMD_SETUP_ARC_BLENDS, IniPinType::Bit));
    out.push_back(traj_item("traj_arc_blend_optimization_depth", &TaskConfig::arc_blend_depth,
                            MOTCMD_SETUP_ARC_BLENDS, IniPinType::S32));
    out.push_back(traj_item("traj_arc_blend_gap_cycles", &TaskConfig::arc_blend_gap_cycles, MOTCMD_SETUP_ARC_BLENDS));
    out.push_back(traj_item("traj_arc_blend_ramp_freq", &TaskConfig::arc_blend_ramp_freq, MOTCMD_SETUP_ARC_BLENDS));
    out.push_back(traj_item("traj_arc_blend_tangent_kink_ratio", &TaskConfig::arc_blend_kink_ratio,
                            MOTCMD_SETUP_ARC_BLENDS));
    return out;
}

std::vector<motion_command> inihal_apply(const std::vector<IniItem>& items, const std::vector<double>& values,
                                         TaskConfig& cfg)
{
    std::vector<const IniItem*> changed;
    for (size_t i = 0; i < items.size() && i < values.size(); ++i) {
        // NaN never equals itself: a NaN pin would be "changed" every cycle
        if (!std::isfinite(values[i]) || values[i] == items[i].get(cfg))
            continue;
        items[i].set(cfg, values[i]);
        changed.push_back(&items[i]);
    }
    // the commands from the configuration with every change in it
    Cmds out;
    std::set<std::tuple<int, int, int>> sent;
    for (const IniItem* it : changed)
        for (const motion_command& c : it->send(cfg))
            if (sent.insert({c.command, c.joint, c.axis}).second)
                out.push_back(c);
    return out;
}

}  // namespace hal::task
