// SPDX-License-Identifier: GPL-2.0-or-later
// task_canon.cpp - canonical calls -> task's work queue (see task_canon.hpp).
#include "task_canon.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hal::task {

using rs274::Pos;

static std::string num(double v)
{
    char b[48];
    std::snprintf(b, sizeof b, "%.17g", v);
    return b;
}

motion_command TaskCanon::base(int type) const
{
    motion_command c{};
    c.command = type;
    c.axis = -1;
    c.id = view_.line;
    return c;
}

void TaskCanon::push(Item it)
{
    if (skip_ && it.kind != Item::End)
        return;   // RUN from a line: blocks before it set state only
    it.line = view_.line;
    queue_.push_back(std::move(it));
}

void TaskCanon::push_cmd(const motion_command& c, bool wait_motion)
{
    Item it;
    it.cmd = c;
    it.wait_motion = wait_motion;
    push(it);
}

motion_command TaskCanon::move_cmd(int type, int motion_type, const Pos& end, double vel, double ini_maxvel,
                                   double acc) const
{
    motion_command c = base(type);
    c.motion_type = motion_type;
    for (int a = 0; a < rs274::NUM_AXES; ++a)
        c.pos.v[a] = end[a];
    c.vel = vel;
    c.ini_maxvel = ini_maxvel;
    c.acc = acc;
    return c;
}

void TaskCanon::block_begin(const std::string& file, int line)
{
    view_.file = file;
    view_.line = line;
}

void TaskCanon::set_g5x_offset(int index, const Pos& offset)
{
    view_.g5x_index = index;
    view_.g5x = offset;
}

void TaskCanon::use_tool_length_offset(const Pos& offset)
{
    view_.tool_offset = offset;
    // motion reports it (motion.tool_offset) to displays; it does not shift anything
    motion_command c = base(MOTCMD_SET_OFFSET);
    for (int a = 0; a < rs274::NUM_AXES; ++a)
        c.pos.v[a] = offset[a];
    push_cmd(c);
}

void TaskCanon::set_motion_control_mode(rs274::MotionControl m, double tolerance)
{
    view_.motion_control = m;
    view_.tolerance = tolerance;
    motion_command c = base(MOTCMD_SET_TERM_COND);
    c.termCond = m == rs274::MotionControl::CONTINUOUS ? MOTION_TERM_PARABOLIC
                 : m == rs274::MotionControl::EXACT_STOP ? MOTION_TERM_STOP
                                                         : MOTION_TERM_EXACT;
    c.tolerance = m == rs274::MotionControl::CONTINUOUS ? tolerance : 0;
    push_cmd(c);
}

void TaskCanon::set_feed_mode(int, rs274::FeedMode m)
{
    view_.feed_mode = m;
}

void TaskCanon::line_limits(const Pos& start, const Pos& end, double& vel, double& acc) const
{
    double d[rs274::NUM_AXES];
    double xyz = 0, uvw = 0, abc = 0;
    for (int a = 0; a < rs274::NUM_AXES; ++a) {
        d[a] = std::fabs(end[a] - start[a]);
        (a < 3 ? xyz : a < 6 ? abc : uvw) += d[a] * d[a];
    }
    // the planner's length: XYZ if it moves, else UVW, else ABC (LinuxCNC's rule)
    double len = std::sqrt(xyz > 1e-18 ? xyz : uvw > 1e-18 ? uvw : abc);
    vel = cfg_.max_vel;
    acc = cfg_.max_acc;
    if (!(len > 1e-9)) {
        return;
    }
    for (int a = 0; a < rs274::NUM_AXES; ++a) {
        if (d[a] < 1e-12 || !cfg_.axis[a].present)
            continue;
        vel = std::min(vel, cfg_.axis[a].max_vel * len / d[a]);
        acc = std::min(acc, cfg_.axis[a].max_acc * len / d[a]);
    }
}

double TaskCanon::feed_velocity(const Pos& start, const Pos& end, double vel_limit) const
{
    double v = 0;
    switch (view_.feed_mode) {
    case rs274::FeedMode::UNITS_PER_MINUTE:
        v = view_.feed / 60.0;
        break;
    case rs274::FeedMode::INVERSE_TIME: {
        // F is moves per minute: the whole move takes 60/F seconds
        double l = 0;
        for (int a = 0; a < 3; ++a)
            l += (end[a] - start[a]) * (end[a] - start[a]);
        v = std::sqrt(l) * view_.feed / 60.0;
        break;
    }
    case rs274::FeedMode::UNITS_PER_REV:
        v = view_.feed * std::fabs(view_.speed[0]) / 60.0;
        break;
    }
    return std::min(v, vel_limit);
}

void TaskCanon::move(int type, int motion_type, const Pos& end, double vel, double ini_maxvel, double acc)
{
    push_cmd(move_cmd(type, motion_type, end, vel, ini_maxvel, acc));
    pos_ = end;
}

void TaskCanon::straight_traverse(const Pos& end)
{
    double vel, acc;
    line_limits(pos_, end, vel, acc);
    move(MOTCMD_SET_LINE, MOTION_TYPE_TRAVERSE, end, vel, vel, acc);
}

void TaskCanon::straight_feed(const Pos& end)
{
    double vel, acc;
    line_limits(pos_, end, vel, acc);
    move(MOTCMD_SET_LINE, MOTION_TYPE_FEED, end, feed_velocity(pos_, end, vel), vel, acc);
}

void TaskCanon::arc_feed(double first_end, double second_end, double first_center, double second_center,
                         int rotation, const Pos& end)
{
    (void)first_end;
    (void)second_end;   // the same values are in `end`
    int a1 = 0, a2 = 1, an = 2;   // XY
    if (view_.plane == rs274::Plane::YZ) {
        a1 = 1;
        a2 = 2;
        an = 0;
    } else if (view_.plane == rs274::Plane::XZ) {
        a1 = 2;   // the canon gives ZX order
        a2 = 0;
        an = 1;
    }
    // the slowest of the plane's axes (and the helix axis when it moves) bounds the arc
    double vel = cfg_.max_vel, acc = cfg_.max_acc;
    for (int a : {a1, a2, an}) {
        if (a == an && std::fabs(end[an] - pos_[an]) < 1e-12)
            continue;
        if (cfg_.axis[a].present) {
            vel = std::min(vel, cfg_.axis[a].max_vel);
            acc = std::min(acc, cfg_.axis[a].max_acc);
        }
    }
    motion_command c = move_cmd(MOTCMD_SET_CIRCLE, MOTION_TYPE_ARC, end, feed_velocity(pos_, end, vel), vel, acc);
    c.center[a1] = first_center;
    c.center[a2] = second_center;
    c.center[an] = pos_[an];
    c.normal[an] = rotation >= 0 ? 1.0 : -1.0;
    c.turn = std::abs(rotation) - 1;
    if (c.turn < 0)
        c.turn = 0;
    push_cmd(c);
    pos_ = end;
}

void TaskCanon::straight_probe(const Pos& end, rs274::ProbeType type)
{
    Item clear;
    clear.cmd = base(MOTCMD_CLEAR_PROBE_FLAGS);
    clear.wait_motion = true;
    push(clear);
    double vel, acc;
    line_limits(pos_, end, vel, acc);
    motion_command c = move_cmd(MOTCMD_PROBE, MOTION_TYPE_PROBING, end, feed_velocity(pos_, end, vel), vel, acc);
    c.probe_type = static_cast<int>(type);   // 0 G38.2, 1 G38.3, 2 G38.4, 3 G38.5
    push_cmd(c);
    pos_ = end;
}

rs274::ProbeResult TaskCanon::probe_result()
{
    if (skip_)
        return {pos_, false};
    rs274::ProbeResult r = host_.probe_result();
    pos_ = r.position;   // motion stopped where the probe tripped (or at the end)
    return r;
}

void TaskCanon::rigid_tap(const Pos& end, double scale)
{
    double vel, acc;
    line_limits(pos_, end, vel, acc);
    motion_command c = move_cmd(MOTCMD_RIGID_TAP, MOTION_TYPE_FEED, end, feed_velocity(pos_, end, vel), vel, acc);
    c.scale = scale;
    push_cmd(c);
    // a rigid tap returns to where it started
}

void TaskCanon::start_speed_feed_synch(int spindle, double feed_per_rev, bool velocity_mode)
{
    motion_command c = base(MOTCMD_SET_SPINDLESYNC);
    c.spindle = spindle < 0 ? 0 : spindle;
    c.spindlesync = feed_per_rev;
    c.flags = velocity_mode ? 1 : 0;
    push_cmd(c);
}

void TaskCanon::stop_speed_feed_synch()
{
    motion_command c = base(MOTCMD_SET_SPINDLESYNC);
    c.spindle = 0;
    push_cmd(c);
}

void TaskCanon::dwell(double seconds)
{
    Item it;
    it.kind = Item::Delay;
    it.seconds = seconds;
    it.wait_motion = true;
    push(it);
}

void TaskCanon::set_spindle_speed(int spindle, double rpm)
{
    int s = spindle < 0 ? 0 : std::min(spindle, MOTION_MAX_SPINDLES - 1);
    view_.speed[s] = rpm;
}

void TaskCanon::set_spindle_mode(int spindle, double css_factor, double max_rpm)
{
    int s = spindle < 0 ? 0 : std::min(spindle, MOTION_MAX_SPINDLES - 1);
    css_factor_[s] = css_factor;
    css_max_[s] = max_rpm;
}

void TaskCanon::spindle_on(int spindle, int dir)
{
    int s = spindle < 0 ? 0 : std::min(spindle, MOTION_MAX_SPINDLES - 1);
    motion_command c = base(MOTCMD_SPINDLE_ON);
    c.spindle = spindle;
    double speed = css_factor_[s] != 0 ? css_max_[s] : view_.speed[s];
    c.vel = dir * std::fabs(speed);
    c.css_factor = dir * css_factor_[s];
    c.wait_for_at_speed = 1;
    push_cmd(c, true);
}

void TaskCanon::stop_spindle_turning(int spindle)
{
    motion_command c = base(MOTCMD_SPINDLE_OFF);
    c.spindle = spindle;
    push_cmd(c, true);
}

void TaskCanon::orient_spindle(int spindle, double degrees, int direction)
{
    motion_command c = base(MOTCMD_SPINDLE_ORIENT);
    c.spindle = spindle;
    c.orientation = degrees;
    c.mode = direction;
    push_cmd(c, true);
}

void TaskCanon::wait_spindle_orient_complete(int, double timeout)
{
    // the orient handshake is motion's; task waits for motion (and at most timeout)
    (void)timeout;
    dwell(0);
}

void TaskCanon::speed_override_enable(int spindle, bool on)
{
    motion_command c = base(MOTCMD_SS_ENABLE);
    c.spindle = spindle;
    c.mode = on ? 1 : 0;
    push_cmd(c);
}

void TaskCanon::enable(int type, bool on)
{
    motion_command c = base(type);
    c.mode = on ? 1 : 0;
    push_cmd(c);
}

void TaskCanon::io(std::vector<std::string> words, bool wait_motion)
{
    Item it;
    it.kind = Item::Io;
    it.io = std::move(words);
    it.wait_motion = wait_motion;
    push(it);
}

void TaskCanon::msg(const std::string& kind, const std::string& text)
{
    Item it;
    it.kind = Item::Message;
    it.msg_kind = kind;
    it.text = text;
    push(it);
}

void TaskCanon::special(Item::Kind k)
{
    Item it;
    it.kind = k;
    it.wait_motion = true;
    push(it);
}

void TaskCanon::select_tool(int tool)
{
    view_.selected_tool = tool;
    io({"TOOL_PREPARE", std::to_string(tool)}, false);
}

void TaskCanon::change_tool(int)
{
    io({"TOOL_LOAD"});
}

void TaskCanon::change_tool_number(int tool)
{
    io({"TOOL_SET_NUMBER", std::to_string(tool)});
}

void TaskCanon::set_tool_table_entry(int tool, int pocket, const Pos& offset, double diameter, double frontangle,
                                     double backangle, int orientation)
{
    std::vector<std::string> w = {"TOOL_SET_OFFSET", std::to_string(tool), std::to_string(pocket)};
    for (int a = 0; a < rs274::NUM_AXES; ++a)
        w.push_back(num(offset[a]));
    w.push_back(num(diameter));
    w.push_back(num(frontangle));
    w.push_back(num(backangle));
    w.push_back(std::to_string(orientation));
    io(std::move(w));
}

// M62/M63 and M67 go with the next move; M64/M65 and M68 act now, once the moves
// before them have finished.
void TaskCanon::output(bool analog, int index, double value, bool now)
{
    motion_command c = base(analog ? MOTCMD_SET_AOUT : MOTCMD_SET_DOUT);
    c.out = index;
    if (analog)
        c.aout_start = c.aout_end = value;
    else
        c.start = c.end = value != 0 ? 1 : 0;
    c.now = now ? 1 : 0;
    push_cmd(c, now);
}

void TaskCanon::set_motion_output_bit(int index, bool on) { output(false, index, on ? 1 : 0, false); }
void TaskCanon::set_aux_output_bit(int index, bool on) { output(false, index, on ? 1 : 0, true); }
void TaskCanon::set_motion_output_value(int index, double value) { output(true, index, value, false); }
void TaskCanon::set_aux_output_value(int index, double value) { output(true, index, value, true); }

double TaskCanon::wait_input(int index, bool analog, rs274::WaitType type, double timeout)
{
    if (skip_)
        return 0;
    return host_.wait_input(index, analog, type, timeout);
}

int TaskCanon::user_m_code(int code, const std::string& path, double p, double q)
{
    if (skip_)
        return 0;
    return host_.user_m_code(code, path, p, q);
}

}  // namespace hal::task
