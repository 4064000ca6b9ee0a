// SPDX-License-Identifier: GPL-2.0-or-later
// task_status.cpp - the status block clients read (docs/bus.md "Status keys"): task,
// interpreter, motion (traj, joints, axes, spindles), io and the tool table.
#include <cstdio>

#include "task.hpp"

namespace hal::task {

static std::string f(double v)
{
    char b[40];
    std::snprintf(b, sizeof b, "%.6f", v);
    return b;
}

static std::string pose(const double* v, const std::string& letters)
{
    // the configured axes, in X Y Z A B C U V W order
    std::string s;
    for (int a = 0; a < MOTION_MAX_AXES; ++a)
        if (letters.find(AXIS_LETTERS[a]) != std::string::npos)
            s += (s.empty() ? "" : " ") + f(v[a]);
    return s;
}

// "G1 G17 G91.1": G codes come times ten (interp.hpp), M codes as they are
static std::string code_list(char letter, const std::vector<int>& codes)
{
    std::string s;
    for (int c : codes) {
        if (c < 0)
            continue;   // a group with nothing in effect
        char b[24];
        if (letter == 'G' && c % 10)
            std::snprintf(b, sizeof b, "G%d.%d", c / 10, c % 10);
        else
            std::snprintf(b, sizeof b, "%c%d", letter, letter == 'G' ? c / 10 : c);
        s += (s.empty() ? "" : " ") + std::string(b);
    }
    return s;
}

static const char* motion_mode_name(int s)
{
    switch (s) {
    case MOTION_FREE: return "FREE";
    case MOTION_TELEOP: return "TELEOP";
    case MOTION_COORD: return "COORD";
    default: return "DISABLED";
    }
}

bus::StatusLines Task::status_lines() const
{
    bus::StatusLines st;
    auto add = [&](const std::string& k, const std::string& v) { st.emplace_back(k, v); };
    auto b = [](bool x) { return std::string(x ? "1" : "0"); };
    const TaskCanon::View& iv = canon_->view();
    std::string axes;   // distinct configured letters in axis order
    for (int a = 0; a < MOTION_MAX_AXES; ++a)
        if (cfg_.axis[a].present)
            axes += AXIS_LETTERS[a];

    add("version", std::to_string(bus::PROTOCOL_VERSION));
    add("task.heartbeat", std::to_string(heartbeat_));
    add("task.ini", bus::sanitize(cfg_.ini_path, 1000));
    add("task.state", state_name(state_));
    add("task.state_requested", state_name(requested_state_));
    add("task.mode", mode_name(mode_));
    add("task.interp", interp_name(interp_state_));
    add("task.motion_ready", b(motion_ready_));
    add("task.file", bus::sanitize(program_open_ ? program_file_ : "", 1000));
    add("task.line", std::to_string(program_running_ || reading_ ? current_line_ : 0));
    add("task.motion_line", std::to_string(motion_line_));
    add("task.queue", std::to_string(canon_->queue().size()));
    add("task.mdi_queue", std::to_string(mdi_queue_.size() + (mdi_running_ ? 1 : 0)));
    add("task.paused", b(paused_));
    add("task.optional_stop", b(optional_stop_));
    add("task.block_delete", b(block_delete_));
    add("task.debug", std::to_string(debug_));
    add("task.last_error", bus::sanitize(last_error_, 1000));
    add("task.program_units", iv.units == rs274::Units::MM ? "MM" : "INCH");
    add("task.feed_rate", f(iv.feed));
    add("task.spindle_speed", f(iv.speed[0]));
    add("task.feed_mode", iv.feed_mode == rs274::FeedMode::INVERSE_TIME   ? "G93"
                          : iv.feed_mode == rs274::FeedMode::UNITS_PER_REV ? "G95"
                                                                           : "G94");
    add("task.plane", iv.plane == rs274::Plane::XY ? "G17" : iv.plane == rs274::Plane::XZ ? "G18" : "G19");
    add("task.motion_control", iv.motion_control == rs274::MotionControl::EXACT_STOP   ? "G61.1"
                               : iv.motion_control == rs274::MotionControl::EXACT_PATH ? "G61"
                                                                                       : "G64");
    add("task.tolerance", f(iv.tolerance));
    add("task.g5x_index", std::to_string(iv.g5x_index));
    add("task.g5x_offset", pose(iv.g5x.data(), axes));
    add("task.g92_offset", pose(iv.g92.data(), axes));
    add("task.rotation_xy", f(iv.rotation));
    add("task.tool_offset", pose(iv.tool_offset.data(), axes));
    add("task.selected_tool", std::to_string(iv.selected_tool));
    add("task.active_gcodes", code_list('G', interp_->active_g_codes()));
    add("task.active_mcodes", code_list('M', interp_->active_m_codes()));

    add("traj.linear_units", cfg_.linear_units);
    add("traj.units_per_mm", f(cfg_.units_per_mm));
    add("traj.angular_units", cfg_.angular_units);
    add("traj.coordinates", cfg_.coordinates);
    add("traj.axes", axes);
    add("traj.joints", std::to_string(cfg_.joints));
    add("traj.spindles", std::to_string(cfg_.spindles));
    add("traj.mode", motion_mode_name(mst_.motion_state));
    add("traj.enabled", b(motion_enabled()));
    add("traj.inpos", b(mst_.motionFlag & MOTION_FLAG_INPOS));
    add("traj.queue", std::to_string(mst_.depth));
    add("traj.active_queue", std::to_string(mst_.activeDepth));
    add("traj.queue_full", b(mst_.queueFull));
    add("traj.paused", b(mst_.paused));
    add("traj.id", std::to_string(mst_.id));
    add("traj.feed_scale", f(mst_.feed_scale));
    add("traj.rapid_scale", f(mst_.rapid_scale));
    add("traj.max_velocity", f(mst_.vel_limit));
    add("traj.current_vel", f(mst_.current_vel));
    add("traj.distance_to_go", f(mst_.distance_to_go));
    add("traj.position", pose(mst_.carte_pos_cmd.v, axes));
    add("traj.actual_position", pose(mst_.carte_pos_fb.v, axes));
    add("traj.probed_position", pose(mst_.probedPos.v, axes));
    add("traj.probe_tripped", b(mst_.probeTripped));
    add("traj.probing", b(mst_.probing));
    add("traj.probe_val", b(mst_.probeVal));
    add("traj.kinematics_type", std::to_string(mst_.kinematics_type));
    add("traj.all_homed", b(all_homed()));
    add("traj.on_soft_limit", b(mst_.on_soft_limit));
    add("traj.jogging", b(mst_.jogging_active));
    add("traj.feed_override_enabled", b(mst_.enables_new & MOTION_FS_ENABLED));
    add("traj.feed_hold_enabled", b(mst_.enables_new & MOTION_FH_ENABLED));
    add("traj.adaptive_feed_enabled", b(mst_.enables_new & MOTION_AF_ENABLED));
    for (int j = 0; j < cfg_.joints && j < MOTION_MAX_JOINTS; ++j) {
        const motion_joint_status& js = mst_.joint[j];
        std::string p = "joint." + std::to_string(j) + ".";
        add(p + "type", cfg_.joint[j].type == 2 ? "ANGULAR" : "LINEAR");
        add(p + "homed", b(js.homed));
        add(p + "homing", b(js.homing));
        add(p + "enabled", b(js.flag & JOINT_FLAG_ENABLE));
        add(p + "fault", b(js.flag & JOINT_FLAG_FAULT));
        add(p + "inpos", b(js.flag & JOINT_FLAG_INPOS));
        add(p + "pos_cmd", f(js.pos_cmd));
        add(p + "pos_fb", f(js.pos_fb));
        add(p + "velocity", f(js.vel_cmd));
        add(p + "ferror", f(js.ferror));
        add(p + "ferror_high_mark", f(js.ferror_high_mark));
        add(p + "min_limit", f(js.min_pos_limit));
        add(p + "max_limit", f(js.max_pos_limit));
        add(p + "min_hard_limit", b(js.flag & JOINT_FLAG_MIN_HARD_LIMIT));
        add(p + "max_hard_limit", b(js.flag & JOINT_FLAG_MAX_HARD_LIMIT));
        add(p + "min_soft_limit", b(js.homed && js.pos_cmd <= js.min_pos_limit));
        add(p + "max_soft_limit", b(js.homed && js.pos_cmd >= js.max_pos_limit));
        add(p + "override_limits", b(mst_.overrideLimitMask & (3u << (2 * j))));
        add(p + "backlash", f(js.backlash));
        // motion's own limits (the INI values, or the ini.N.* pins since)
        add(p + "max_velocity", f(js.vel_limit));
        add(p + "max_acceleration", f(js.acc_limit));
        add(p + "max_ferror", f(js.max_ferror));
        add(p + "min_ferror", f(js.min_ferror));
    }
    for (int a = 0; a < MOTION_MAX_AXES; ++a) {
        if (!cfg_.axis[a].present)
            continue;
        std::string p = std::string("axis.") + ini::axis_lower(a) + ".";
        add(p + "pos_cmd", f(mst_.carte_pos_cmd.v[a]));
        add(p + "pos_fb", f(mst_.carte_pos_fb.v[a]));
        add(p + "min_limit", f(mst_.axis[a].min_pos_limit));
        add(p + "max_limit", f(mst_.axis[a].max_pos_limit));
        add(p + "velocity", f(mst_.axis[a].teleop_vel_cmd));
        add(p + "max_velocity", f(mst_.axis[a].vel_limit));
        add(p + "max_acceleration", f(mst_.axis[a].acc_limit));
    }
    for (int s = 0; s < cfg_.spindles && s < MOTION_MAX_SPINDLES; ++s) {
        const motion_spindle_status& sp = mst_.spindle[s];
        std::string p = "spindle." + std::to_string(s) + ".";
        add(p + "speed", f(sp.speed));
        add(p + "override", f(sp.scale));
        add(p + "direction", std::to_string(sp.direction));
        add(p + "enabled", b(sp.state != 0));
        add(p + "brake", b(sp.brake));
        add(p + "at_speed", b(sp.at_speed));
        add(p + "orient_state", std::to_string(sp.orient_state));
    }
    add("io.connected", b(io_.connected));
    add("io.estop", b(io_estop_.estop()));
    add("io.mist", b(io_.mist));
    add("io.flood", b(io_.flood));
    add("io.lube", b(io_.lube));
    add("io.lube_level", b(io_.lube_level));
    add("io.tool_in_spindle", std::to_string(io_.tool));
    add("io.pocket_prepped", std::to_string(io_.pocket_prepped));
    add("io.tool_prepped", std::to_string(io_.prep_tool));
    add("io.tool_from_pocket", std::to_string(io_.from_pocket));
    add("tool.count", std::to_string(io_.tools.size()));
    for (size_t i = 0; i < io_.tools.size(); ++i)
        add("tool." + std::to_string(i), bus::sanitize(io_.tools[i], 400));
    return st;
}

}  // namespace hal::task
