// SPDX-License-Identifier: GPL-2.0-or-later
// halui_status.cpp - task's status block -> StatusView (halui_status.hpp).
#include "halui_status.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>

#include "halui_config.hpp"

namespace hal::halui {

namespace {

using Map = std::map<std::string, std::string>;

const std::string* get(const Map& st, const std::string& key)
{
    auto it = st.find(key);
    return it == st.end() ? nullptr : &it->second;
}

void text(const Map& st, const std::string& key, std::string& v)
{
    if (auto s = get(st, key))
        v = *s;
}

void flag(const Map& st, const std::string& key, bool& v)
{
    if (auto s = get(st, key))
        v = *s == "1";
}

void real(const Map& st, const std::string& key, double& v)
{
    if (auto s = get(st, key)) {
        v = std::strtod(s->c_str(), nullptr);
        if (!std::isfinite(v))
            v = 0;
    }
}

// "1.0 2.0 3.0": one value per configured axis, in the order of traj.axes ("XYZ")
void pose(const Map& st, const std::string& key, const std::string& axes, double* out)
{
    const std::string* s = get(st, key);
    if (!s)
        return;
    ini::values_by_axis(axes, s->c_str(), out);
}

// the D field of tool 'tool' in the table lines "T1 P1 Z+10.000000 D+6.000000 ;remark"
double diameter_of(const Map& st, int tool)
{
    if (tool <= 0)
        return 0;
    long count = 0;
    if (auto s = get(st, "tool.count"))
        count = std::strtol(s->c_str(), nullptr, 10);
    const std::string prefix = "T" + std::to_string(tool) + " ";
    for (long i = 0; i < count && i < 100000; ++i) {
        const std::string* line = get(st, "tool." + std::to_string(i));
        if (!line || line->rfind(prefix, 0) != 0)
            continue;
        std::string fields = line->substr(0, line->find(';'));
        size_t d = fields.find(" D");
        return d == std::string::npos ? 0 : std::strtod(fields.c_str() + d + 2, nullptr);
    }
    return 0;
}

}  // namespace

StatusView parse_status(const Map& st, int joints, int spindles)
{
    StatusView s;
    text(st, "task.state", s.state);
    text(st, "task.mode", s.mode);
    text(st, "task.interp", s.interp);
    text(st, "traj.mode", s.traj_mode);
    text(st, "task.file", s.file);
    flag(st, "task.paused", s.paused);
    flag(st, "task.optional_stop", s.optional_stop);
    flag(st, "task.block_delete", s.block_delete);
    flag(st, "io.mist", s.mist);
    flag(st, "io.flood", s.flood);
    flag(st, "io.lube", s.lube);
    real(st, "traj.units_per_mm", s.units_per_mm);
    real(st, "traj.feed_scale", s.feed_scale);
    real(st, "traj.rapid_scale", s.rapid_scale);
    real(st, "traj.max_velocity", s.max_velocity);
    real(st, "task.spindle_speed", s.spindle_speed);
    real(st, "task.rotation_xy", s.rotation_xy);
    std::string axes;
    text(st, "traj.axes", axes);
    pose(st, "traj.position", axes, s.pos_cmd);
    pose(st, "traj.actual_position", axes, s.pos_fb);
    pose(st, "task.g5x_offset", axes, s.g5x);
    pose(st, "task.g92_offset", axes, s.g92);
    pose(st, "task.tool_offset", axes, s.tool_offset);
    s.joints.resize(static_cast<size_t>(joints));
    for (int j = 0; j < joints; ++j) {
        const std::string p = "joint." + std::to_string(j) + ".";
        JointStatus& js = s.joints[static_cast<size_t>(j)];
        flag(st, p + "homed", js.homed);
        flag(st, p + "fault", js.fault);
        flag(st, p + "min_soft_limit", js.min_soft);
        flag(st, p + "max_soft_limit", js.max_soft);
        flag(st, p + "min_hard_limit", js.min_hard);
        flag(st, p + "max_hard_limit", js.max_hard);
        flag(st, p + "override_limits", js.override_limits);
    }
    s.spindles.resize(static_cast<size_t>(spindles));
    for (int k = 0; k < spindles; ++k) {
        const std::string p = "spindle." + std::to_string(k) + ".";
        SpindleStatus& sp = s.spindles[static_cast<size_t>(k)];
        real(st, p + "speed", sp.speed);
        real(st, p + "override", sp.scale);
        double dir = 0;
        real(st, p + "direction", dir);
        sp.direction = dir > 0 ? 1 : dir < 0 ? -1 : 0;
        flag(st, p + "enabled", sp.enabled);
        flag(st, p + "brake", sp.brake);
    }
    double tool = 0;
    real(st, "io.tool_in_spindle", tool);
    s.tool = static_cast<int>(tool);
    s.tool_diameter = diameter_of(st, s.tool);
    return s;
}

double relative_position(const StatusView& s, int a)
{
    auto base = [&](int k) { return s.pos_fb[k] - s.g5x[k] - s.tool_offset[k]; };
    double v = base(a);
    if ((a == 0 || a == 1) && s.rotation_xy != 0) {
        double r = -s.rotation_xy * M_PI / 180.0;
        double x = base(0), y = base(1);
        v = a == 0 ? x * std::cos(r) - y * std::sin(r) : x * std::sin(r) + y * std::cos(r);
    }
    return v - s.g92[a];
}

}  // namespace hal::halui
