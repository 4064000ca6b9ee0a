// SPDX-License-Identifier: GPL-2.0-or-later
// subcommands_set.cpp - SET: the session's and the server's settings, and the
// commands sent to task over the bus (emcrsh-and-halui.md 1.3, docs/bus.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "hal/numbers.hpp"
#include "ini/axes.hpp"
#include "session.hpp"

namespace hal::emcrsh {

static bool number(const std::string& s, double& out) { return parse_finite(s, out); }
// joint, tool and line numbers: six digits are plenty
static bool integer(const std::string& s, long& out) { return parse_integer(s, out, -1000000, 1000000); }

static std::string g(double v)
{
    char b[40];
    std::snprintf(b, sizeof b, "%.10g", v);
    return b;
}

// ON/OFF: 1/0, -1 for anything else
static int on_off(const std::string& s)
{
    std::string u = upper(s);
    return u == "ON" ? 1 : u == "OFF" ? 0 : -1;
}

// a joint number or an axis letter, as the bus takes it
static bool joint_or_axis(const std::string& s, std::string& out)
{
    long j = 0;
    std::string u = upper(s);
    if (u.size() == 1 && hal::ini::axis_index(u[0]) >= 0) {
        out = u;
        return true;
    }
    if (!integer(s, j) || j < 0)
        return false;
    out = std::to_string(j);
    return true;
}

bool Session::send(const std::string& bus_line)
{
    Wait w;
    double t;
    {
        std::lock_guard<std::mutex> gd(shared_.mu);
        w = shared_.set_wait;
        t = shared_.timeout;
    }
    auto r = m_.command(bus_line, w, t);
    if (!r)
        error_ = r.error().message;   // GET ERROR tells why
    return static_cast<bool>(r);
}

bool Session::set_value(const std::string& sub, const std::vector<std::string>& args, const std::string& rest)
{
    std::string a0 = args.empty() ? "" : upper(args[0]);
    if (sub == "ECHO" || sub == "VERBOSE") {
        int v = on_off(a0);
        if (v < 0)
            return false;
        (sub == "ECHO" ? echo_ : verbose_) = v == 1;
        return true;
    }
    if (sub == "ENABLE") {
        if (args.empty())
            return false;
        if (a0 == "OFF") {   // "OFF" is never a password
            int me = id_;
            shared_.enabled.compare_exchange_strong(me, 0);
            return true;
        }
        if (args[0] != shared_.opt.enable_pw)
            return false;
        shared_.enabled = id_;   // only one session is enabled: this one takes it
        return true;
    }
    if (sub == "CONFIG" || sub == "INIFILE" || sub == "PLAT" || sub == "INI")
        return true;   // accepted, nothing to change (emcrsh(1))
    if (sub == "COMM_MODE") {
        if (a0 != "ASCII" && a0 != "BINARY")
            return false;
        comm_mode_ = a0;
        return true;
    }
    if (sub == "COMM_PROT") {
        // a version up to the server's own (1.1)
        double v = 0;
        if (args.empty() || !number(args[0], v) || v <= 0 || v > 1.1)
            return false;
        comm_prot_ = args[0];
        return true;
    }
    if (sub == "SET_WAIT" || sub == "UPDATE" || sub == "TIMEOUT" || sub == "SET_TIMEOUT" ||
        sub == "LINEAR_UNIT_CONVERSION" || sub == "ANGULAR_UNIT_CONVERSION") {
        std::lock_guard<std::mutex> gd(shared_.mu);
        if (sub == "SET_WAIT") {
            if (a0 != "NONE" && a0 != "RECEIVED" && a0 != "DONE")
                return false;
            shared_.set_wait = a0 == "NONE" ? Wait::NONE : a0 == "DONE" ? Wait::DONE : Wait::RECEIVED;
        } else if (sub == "UPDATE") {
            if (a0 != "NONE" && a0 != "AUTO")
                return false;
            shared_.update_auto = a0 == "AUTO";
        } else if (sub == "LINEAR_UNIT_CONVERSION") {
            if (a0 != "INCH" && a0 != "MM" && a0 != "CM" && a0 != "AUTO" && a0 != "CUSTOM")
                return false;
            shared_.linear_conv = a0;
        } else if (sub == "ANGULAR_UNIT_CONVERSION") {
            if (a0 != "DEG" && a0 != "RAD" && a0 != "GRAD" && a0 != "AUTO" && a0 != "CUSTOM")
                return false;
            shared_.angular_conv = a0;
        } else {
            double t = 0;
            if (args.empty() || !number(args[0], t))
                return false;
            shared_.timeout = t;
        }
        return true;
    }
    if (sub == "WAIT") {
        if (a0 != "RECEIVED" && a0 != "DONE")
            return false;
        double t;
        {
            std::lock_guard<std::mutex> gd(shared_.mu);
            t = shared_.timeout;
        }
        auto r = m_.wait_last(a0 == "DONE" ? Wait::DONE : Wait::RECEIVED, t);
        if (!r)
            error_ = r.error().message;
        return static_cast<bool>(r);
    }
    return set_motion(sub, args, rest);
}

bool Session::set_motion(const std::string& sub, const std::vector<std::string>& args, const std::string& rest)
{
    std::string a0 = args.empty() ? "" : upper(args[0]);
    size_t n = args.size();
    if (sub == "DEBUG") {
        long v = 0;
        return n >= 1 && integer(args[0], v) && send("DEBUG " + std::to_string(v));
    }
    if (sub == "ESTOP" || sub == "MACHINE") {
        int v = on_off(a0);
        if (v < 0)
            return false;
        if (sub == "ESTOP")
            return send(v ? "STATE ESTOP" : "STATE ESTOP_RESET");
        return send(v ? "STATE ON" : "STATE OFF");
    }
    if (sub == "MODE")
        return (a0 == "MANUAL" || a0 == "AUTO" || a0 == "MDI") && send("MODE " + a0);
    if (sub == "MIST" || sub == "FLOOD" || sub == "LUBE")
        return on_off(a0) >= 0 && send(sub + " " + a0);
    if (sub == "SPINDLE" || sub == "BRAKE") {
        // [spindle] word; no spindle number: all of them
        long sp = -1;
        size_t w = 0;
        if (n >= 2 && integer(args[0], sp))
            w = 1;
        if (n <= w || sp < -1)
            return false;
        std::string word = upper(args[w]);
        if (sub == "BRAKE")
            return on_off(word) >= 0 && send("BRAKE " + word + " " + std::to_string(sp));
        if (word != "FORWARD" && word != "REVERSE" && word != "INCREASE" && word != "DECREASE" &&
            word != "CONSTANT" && word != "OFF")
            return false;
        double rpm = 0;
        if (word == "FORWARD" || word == "REVERSE") {
            // the active S word, or 500 rpm when it is 0
            if (!refresh())
                return false;
            rpm = std::fabs(num("task.spindle_speed"));
            if (rpm == 0)
                rpm = 500;
        }
        return send("SPINDLE " + word + " " + g(rpm) + " " + std::to_string(sp));
    }
    if (sub == "TOOL_OFFSET") {
        double t = 0, len = 0, dia = 0;
        if (n < 3 || !number(args[0], t) || !number(args[1], len) || !number(args[2], dia) || t < 0 ||
            t != std::floor(t))
            return false;
        return send("TOOL_OFFSET " + g(t) + " " + g(len) + " " + g(dia));
    }
    if (sub == "LOAD_TOOL_TABLE")
        return !rest.empty() && send("LOAD_TOOL_TABLE " + rest);
    if (sub == "HOME") {
        long j = 0;
        return n >= 1 && integer(args[0], j) && j >= -1 && send("HOME " + std::to_string(j));
    }
    if (sub == "JOG_STOP" || sub == "JOG" || sub == "JOG_INCR") {
        std::string ja;
        double speed = 0, incr = 0;
        size_t need = sub == "JOG_STOP" ? 1 : sub == "JOG" ? 2 : 3;
        if (n < need || !joint_or_axis(args[0], ja))
            return false;
        if (sub == "JOG_STOP")
            return send("JOG_STOP " + ja);
        if (!number(args[1], speed))   // units per minute; the bus takes per second
            return false;
        if (sub == "JOG")
            return send("JOG_CONT " + ja + " " + g(speed / 60.0));
        if (!number(args[2], incr))
            return false;
        return send("JOG_INCR " + ja + " " + g(speed / 60.0) + " " + g(incr));
    }
    if (sub == "FEED_OVERRIDE") {
        double pct = 0;
        if (n < 1 || !number(args[0], pct))
            return false;
        return send("FEED_OVERRIDE " + g(std::max(pct, 0.0) / 100.0));
    }
    if (sub == "SPINDLE_OVERRIDE") {
        // [spindle] percent; one number: every spindle
        double pct = 0;
        long sp = -1;
        if (n < 1 || (n >= 2 && !integer(args[0], sp)) || !number(args[n >= 2 ? 1 : 0], pct) || sp < -1)
            return false;
        return send("SPINDLE_OVERRIDE " + g(std::max(pct, 0.0) / 100.0) + " " + std::to_string(sp));
    }
    if (sub == "MDI")
        return !rest.empty() && send("MDI " + rest);
    if (sub == "TASK_PLAN_INIT")
        return send("PLAN_INIT");
    if (sub == "OPEN") {
        if (rest.empty())
            return false;
        std::string file = rest;
        if (file[0] != '/' && !shared_.opt.path.empty())
            file = shared_.opt.path + "/" + file;   // -d: where programs are
        if (!send("OPEN " + file))
            return false;
        std::lock_guard<std::mutex> gd(shared_.mu);
        shared_.last_program = file;
        return true;
    }
    if (sub == "RUN") {
        long line = 0;
        if (n >= 1 && (!integer(args[0], line) || line < 0))
            return false;   // (-1, the reference's verify mode, is not offered by task)
        // nothing open (a program ended and was closed, or an abort): open the last again
        if (!refresh())
            return false;
        std::string last;
        {
            std::lock_guard<std::mutex> gd(shared_.mu);
            last = shared_.last_program;
        }
        if (key("task.file").empty() && !last.empty() && !send("OPEN " + last))
            return false;
        return send(line > 0 ? "RUN " + std::to_string(line) : "RUN");
    }
    if (sub == "PAUSE" || sub == "RESUME" || sub == "STEP" || sub == "ABORT" || sub == "PROBE_CLEAR")
        return send(sub);
    if (sub == "PROBE") {
        // a probing move towards the point that stops at contact and raises the
        // tripped flag, without an error when there is none (G38.3; MDI mode)
        double x = 0, y = 0, z = 0;
        if (n < 3 || !number(args[0], x) || !number(args[1], y) || !number(args[2], z))
            return false;
        return send("MDI G38.3 X" + g(x) + " Y" + g(y) + " Z" + g(z));
    }
    if (sub == "TELEOP_ENABLE") {
        int v = on_off(a0);
        return v >= 0 && send(std::string("TELEOP ") + (v ? "1" : "0"));
    }
    if (sub == "OVERRIDE_LIMITS") {
        int v = on_off(a0);
        return v >= 0 && send(v ? "OVERRIDE_LIMITS 0" : "OVERRIDE_LIMITS -1");
    }
    if (sub == "OPTIONAL_STOP") {
        int v = a0 == "1" || a0 == "ON" ? 1 : a0 == "0" || a0 == "OFF" ? 0 : -1;
        return v >= 0 && send("OPTIONAL_STOP " + std::to_string(v));
    }
    // status-only subcommands cannot be set
    return false;
}

}  // namespace hal::emcrsh
