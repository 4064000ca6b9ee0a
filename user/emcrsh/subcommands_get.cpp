// SPDX-License-Identifier: GPL-2.0-or-later
// subcommands_get.cpp - GET: every subcommand's reply from the session, the shared
// settings and task's status (emcrsh-and-halui.md 1.3; status keys in docs/bus.md).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

#include "ini/axes.hpp"
#include "ini/ini_file.hpp"
#include "session.hpp"
#include "units.hpp"

namespace hal::emcrsh {


bool Session::refresh()
{
    bool auto_update;
    {
        std::lock_guard<std::mutex> g(shared_.mu);
        auto_update = shared_.update_auto;
    }
    if (st_ && !auto_update)
        return true;   // UPDATE NONE: the last status read
    auto st = m_.status();
    if (!st)
        return false;
    st_ = std::move(*st);
    return true;
}

std::string Session::key(const std::string& k) const
{
    if (!st_)
        return "";
    auto it = st_->find(k);
    return it == st_->end() ? "" : it->second;
}

double Session::num(const std::string& k) const { return std::strtod(key(k).c_str(), nullptr); }

double Session::axis_value(const std::string& field, int axis) const
{
    std::string l(1, hal::ini::axis_lower(axis));
    return num("axis." + l + "." + field);   // 0 for an axis the machine lacks
}

std::vector<double> Session::offsets(const std::string& k) const
{
    // "task.g5x_offset" lists the configured axes (traj.axes) in X..W order
    std::vector<double> v(hal::ini::AXIS_COUNT, 0.0);
    hal::ini::values_by_axis(key("traj.axes"), key(k).c_str(), v.data());
    return v;
}

void Session::take_messages()
{
    for (const bus::Message& msg : m_.take_messages()) {
        if (msg.kind == "ERROR")
            error_ = msg.text;
        else if (msg.kind == "DISPLAY")
            display_ = msg.text;
        else if (msg.kind == "TEXT")
            text_ = msg.text;
    }
}

static bool to_index(const std::string& s, long lo, long hi, long& out)
{
    char* end = nullptr;
    long v = std::strtol(s.c_str(), &end, 10);
    if (s.empty() || *end != '\0' || v < lo || v > hi)
        return false;
    out = v;
    return true;
}

std::optional<std::string> Session::get_position(const std::string& sub, const std::vector<std::string>& args)
{
    if (!refresh())
        return std::nullopt;
    std::vector<double> v(9, 0.0);
    if (sub == "POS_OFFSET") {
        std::vector<double> g5x = offsets("task.g5x_offset"), g92 = offsets("task.g92_offset");
        std::string lin, ang;
        {
            std::lock_guard<std::mutex> g(shared_.mu);
            lin = shared_.linear_conv;
            ang = shared_.angular_conv;
        }
        for (int a = 0; a < 9; ++a) {
            double x = g5x[a] + g92[a];
            v[a] = (a >= 3 && a <= 5)
                       ? convert_angular(x, key("traj.angular_units"), ang)
                       : convert_linear(x, num("traj.units_per_mm"), lin, key("task.program_units"));
        }
        if (args.empty())
            return sub + " " + fmt(v[0]) + " " + fmt(v[1]) + " " + fmt(v[2]) + " " + fmt(v[3]) + " " + fmt(v[4]) +
                   " " + fmt(v[5]);
        // one axis by letter; A/B/C also as R/P/W (the reference's letters)
        static const std::string letters[] = {"X", "Y", "Z", "AR", "BP", "CW"};
        std::string l = upper(args[0]);
        for (int a = 0; a < 6; ++a)
            if (l.size() == 1 && letters[a].find(l[0]) != std::string::npos)
                return sub + " " + l + "  " + fmt(v[a]);
        return std::nullopt;
    }
    bool cmd = sub == "ABS_CMD_POS" || sub == "REL_CMD_POS";
    bool rel = sub.rfind("REL_", 0) == 0;
    std::vector<double> g5x = offsets("task.g5x_offset"), g92 = offsets("task.g92_offset");
    for (int a = 0; a < 9; ++a) {
        v[a] = axis_value(cmd ? "pos_cmd" : "pos_fb", a);
        if (rel)
            v[a] -= g5x[a] + g92[a];
    }
    if (args.empty())
        return sub + " " + fmt(v[0]) + " " + fmt(v[1]) + " " + fmt(v[2]) + " " + fmt(v[3]) + " " + fmt(v[4]) + " " +
               fmt(v[5]);
    long n = 0;
    if (!to_index(args[0], 0, 5, n))
        return std::nullopt;
    return sub + " " + std::to_string(n) + " " + fmt(v[n]);
}

std::optional<std::string> Session::get_joints(const std::string& sub, const std::vector<std::string>& args)
{
    if (!refresh())
        return std::nullopt;
    long joints = std::strtol(key("traj.joints").c_str(), nullptr, 10);
    auto one = [&](long j) -> std::string {
        std::string p = "joint." + std::to_string(j) + ".";
        auto flag = [&](const std::string& k) { return key(p + k) == "1"; };
        if (sub == "JOINT_POS")
            return fmt(num(p + "pos_fb"));
        if (sub == "JOINT_LIMIT")
            return flag("min_hard_limit")   ? "MINHARD"
                   : flag("min_soft_limit") ? "MINSOFT"
                   : flag("max_soft_limit") ? "MAXSOFT"
                   : flag("max_hard_limit") ? "MAXHARD"
                                            : "OK";
        if (sub == "JOINT_FAULT")
            return flag("fault") ? "FAULT" : "OK";
        if (sub == "JOINT_HOMED")
            return flag("homed") ? "YES" : "NO";
        bool angular = key(p + "type") == "ANGULAR";
        if (sub == "JOINT_TYPE")
            return angular ? "ANGULAR" : "LINEAR";
        // JOINT_UNITS
        return angular ? angular_units_name(key("traj.angular_units"))
                       : linear_units_name(num("traj.units_per_mm"));
    };
    if (args.empty()) {
        std::string s = sub;
        for (long j = 0; j < joints; ++j)
            s += " " + one(j);
        return s;
    }
    long j = 0;
    if (!to_index(args[0], 0, joints - 1, j))
        return std::nullopt;
    return sub + " " + std::to_string(j) + " " + one(j);
}

std::optional<std::string> Session::get_units(const std::string& sub)
{
    if (!refresh())
        return std::nullopt;
    std::string lin, ang;
    {
        std::lock_guard<std::mutex> g(shared_.mu);
        lin = shared_.linear_conv;
        ang = shared_.angular_conv;
    }
    if (sub == "PROGRAM_UNITS" || sub == "PROGRAM_LINEAR_UNITS")
        return sub + " " + (key("task.program_units") == "INCH" ? "INCH" : "MM");
    if (sub == "PROGRAM_ANGULAR_UNITS")
        return sub + " DEG";   // the interpreter works in degrees
    if (sub == "USER_LINEAR_UNITS")
        return sub + " " + linear_units_name(num("traj.units_per_mm"));
    if (sub == "USER_ANGULAR_UNITS")
        return sub + " " + angular_units_name(key("traj.angular_units"));
    if (sub == "DISPLAY_LINEAR_UNITS")
        return sub + " " + (lin == "AUTO" ? (key("task.program_units") == "INCH" ? "INCH" : "MM") : lin);
    // DISPLAY_ANGULAR_UNITS
    return sub + " " + (ang == "AUTO" ? "DEG" : ang);
}

std::optional<std::string> Session::get_value(const std::string& sub, const std::vector<std::string>& args)
{
    auto on_off = [](bool b) { return std::string(b ? "ON" : "OFF"); };
    // the session's and the server's own settings
    if (sub == "ECHO")
        return "ECHO " + on_off(echo_);
    if (sub == "VERBOSE")
        return "VERBOSE " + on_off(verbose_);
    if (sub == "ENABLE")
        return "ENABLE " + on_off(enabled());
    if (sub == "CONFIG")
        return std::string("CONFIG");
    if (sub == "COMM_MODE")
        return "COMM_MODE " + comm_mode_;
    if (sub == "COMM_PROT")
        return "COMM_PROT " + comm_prot_;
    if (sub == "PLAT")
        return std::string("PLAT Linux");
    if (sub == "SET_WAIT" || sub == "TIMEOUT" || sub == "SET_TIMEOUT" || sub == "LINEAR_UNIT_CONVERSION" ||
        sub == "ANGULAR_UNIT_CONVERSION") {
        std::lock_guard<std::mutex> g(shared_.mu);
        if (sub == "SET_WAIT")
            return std::string("SET_WAIT ") +
                   (shared_.set_wait == Wait::DONE ? "DONE" : shared_.set_wait == Wait::NONE ? "NONE" : "RECEIVED");
        if (sub == "LINEAR_UNIT_CONVERSION")
            return sub + " " + shared_.linear_conv;
        if (sub == "ANGULAR_UNIT_CONVERSION")
            return sub + " " + shared_.angular_conv;
        return "SET_TIMEOUT " + fmt(shared_.timeout);
    }
    if (sub == "INIFILE") {
        std::string ini = shared_.opt.ini;
        if (ini.empty() && refresh())
            ini = key("task.ini");
        return "INIFILE " + ini;
    }
    if (sub == "INI") {
        // INI <var> <section>: the value in the machine's INI file
        if (args.size() < 2 || shared_.opt.ini.empty())
            return std::nullopt;
        auto ini = ini::IniFile::load(shared_.opt.ini);
        if (!ini)
            return std::nullopt;
        std::string section = args[1];
        if (section.size() > 2 && section.front() == '[' && section.back() == ']')
            section = section.substr(1, section.size() - 2);
        auto v = ini->find(section, args[0]);
        if (!v)
            return std::nullopt;
        return "INI " + *v;
    }
    if (sub == "ERROR" || sub == "OPERATOR_DISPLAY" || sub == "OPERATOR_TEXT") {
        // the latest message of that kind, once; "OK" when there is none
        take_messages();
        std::string& s = sub == "ERROR" ? error_ : sub == "OPERATOR_DISPLAY" ? display_ : text_;
        std::string r = sub + " " + (s.empty() ? "OK" : s);
        s.clear();
        return r;
    }
    if (sub == "TIME") {
        timespec ts{};
        clock_gettime(CLOCK_REALTIME, &ts);
        return "TIME " + fmt(static_cast<double>(ts.tv_sec) + ts.tv_nsec / 1e9);
    }
    if (sub == "ABS_CMD_POS" || sub == "ABS_ACT_POS" || sub == "REL_CMD_POS" || sub == "REL_ACT_POS" ||
        sub == "POS_OFFSET")
        return get_position(sub, args);
    if (sub == "JOINT_POS" || sub == "JOINT_LIMIT" || sub == "JOINT_FAULT" || sub == "JOINT_HOMED" ||
        sub == "JOINT_TYPE" || sub == "JOINT_UNITS")
        return get_joints(sub, args);
    if (sub.find("_UNITS") != std::string::npos)
        return get_units(sub);

    // set-only subcommands (and WAIT, UPDATE, PROBE, PROBE_CLEAR) have nothing to get
    static const char* const set_only[] = {"WAIT", "UPDATE", "PROBE", "PROBE_CLEAR", "HOME", "JOG", "JOG_INCR",
                                           "JOG_STOP", "LOAD_TOOL_TABLE", "MDI", "TASK_PLAN_INIT", "OPEN", "RUN",
                                           "PAUSE", "RESUME", "STEP", "ABORT"};
    for (const char* s : set_only)
        if (sub == s)
            return std::nullopt;

    if (!refresh())
        return std::nullopt;
    auto flag = [&](const std::string& k) { return key(k) == "1"; };
    if (sub == "DEBUG")
        return "DEBUG " + key("task.debug");
    if (sub == "ESTOP")
        return "ESTOP " + on_off(key("task.state") == "ESTOP");
    if (sub == "MACHINE")
        return "MACHINE " + on_off(key("task.state") == "ON");
    if (sub == "MODE") {
        std::string m = key("task.mode");
        return "MODE " + (m == "MANUAL" || m == "AUTO" || m == "MDI" ? m : std::string("?"));
    }
    if (sub == "MIST" || sub == "FLOOD" || sub == "LUBE")
        return sub + " " + on_off(flag("io." + std::string(sub == "MIST" ? "mist" : sub == "FLOOD" ? "flood" : "lube")));
    if (sub == "LUBE_LEVEL")
        return std::string("LUBE_LEVEL ") + (flag("io.lube_level") ? "OK" : "LOW");
    if (sub == "SPINDLE" || sub == "BRAKE" || sub == "SPINDLE_OVERRIDE") {
        long spindles = std::strtol(key("traj.spindles").c_str(), nullptr, 10);
        long s = spindles - 1;   // no number: the last spindle (as the reference ends up)
        if (spindles <= 0 || (!args.empty() && !to_index(args[0], 0, spindles - 1, s)))
            return std::nullopt;
        std::string p = "spindle." + std::to_string(s) + ".";
        if (sub == "BRAKE")
            return "BRAKE " + on_off(flag(p + "brake"));
        if (sub == "SPINDLE_OVERRIDE")
            return sub + " " + std::to_string(s) + " " + std::to_string(std::lround(num(p + "override") * 100));
        double dir = num(p + "direction");
        const char* d = !flag(p + "enabled") || dir == 0 ? "OFF" : dir > 0 ? "FORWARD" : "REVERSE";
        return "SPINDLE " + std::to_string(s) + " " + d;
    }
    if (sub == "TOOL")
        return "TOOL " + key("io.tool_in_spindle");
    if (sub == "TOOL_OFFSET")
        return "TOOL_OFFSET " + fmt(offsets("task.tool_offset")[2]);
    if (sub == "FEED_OVERRIDE")
        return "FEED_OVERRIDE " + std::to_string(std::lround(num("traj.feed_scale") * 100));
    if (sub == "PROGRAM") {
        std::string f = key("task.file");
        return "PROGRAM " + (f.empty() ? std::string("NONE") : f);
    }
    if (sub == "PROGRAM_STATUS") {
        std::string i = key("task.interp");
        const char* s = i == "PAUSED" || (i != "IDLE" && flag("task.paused")) ? "PAUSED"
                        : i == "READING" || i == "WAITING"                   ? "RUNNING"
                                                                             : "IDLE";
        return std::string("PROGRAM_STATUS ") + s;
    }
    if (sub == "PROGRAM_LINE") {
        // the line motion executes while it is behind the interpreter, else the line read
        long line = key("task.interp") == "IDLE" ? 0 : std::strtol(key("task.line").c_str(), nullptr, 10);
        long motion = std::strtol(key("task.motion_line").c_str(), nullptr, 10);
        if (line > 0 && motion > 0 && motion < line)
            line = motion;
        return "PROGRAM_LINE " + std::to_string(line);
    }
    if (sub == "PROGRAM_CODES") {
        char fs[80];
        std::snprintf(fs, sizeof fs, "F%.0f S%.0f", num("task.feed_rate"), std::fabs(num("task.spindle_speed")));
        std::string g = key("task.active_gcodes");
        return "PROGRAM_CODES " + g + (g.empty() ? "" : " ") + fs;
    }
    if (sub == "PROBE_TRIPPED")
        return "PROBE_TRIPPED " + std::string(flag("traj.probe_tripped") ? "1" : "0");
    if (sub == "PROBE_VALUE")
        return "PROBE_VALUE " + std::string(flag("traj.probe_val") ? "1" : "0");
    if (sub == "TELEOP_ENABLE")
        return std::string("TELEOP_ENABLE ") + (key("traj.mode") == "TELEOP" ? "YES" : "NO");
    if (sub == "KINEMATICS_TYPE")
        return "KINEMATICS_TYPE " + key("traj.kinematics_type");
    if (sub == "OVERRIDE_LIMITS")
        return "OVERRIDE_LIMITS " + std::string(flag("joint.0.override_limits") ? "1" : "0");
    if (sub == "OPTIONAL_STOP")
        return "OPTIONAL_STOP " + std::string(flag("task.optional_stop") ? "1" : "0");
    return std::nullopt;
}

}  // namespace hal::emcrsh
