// SPDX-License-Identifier: GPL-2.0-or-later
// motcmd_parse.cpp - motcmd's command table and argument parsing (motcmd_parse.hpp).
#include "motcmd_parse.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <sstream>

namespace hal {

namespace {

using Args = std::vector<std::string>;

struct ParseError {
    std::string message;
};

double number(const std::string& name, const std::string& s)
{
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end || errno == ERANGE || !std::isfinite(v))
        throw ParseError{name + ": '" + s + "' is not a number"};
    return v;
}

int integer(const std::string& name, const std::string& s)
{
    char* end = nullptr;
    errno = 0;
    long v = std::strtol(s.c_str(), &end, 0);
    if (s.empty() || *end || errno == ERANGE || v < -2147483647L || v > 2147483647L)
        throw ParseError{name + ": '" + s + "' is not an integer"};
    return static_cast<int>(v);
}

int axis_index(char c)
{
    const char* letters = "xyzabcuvw";
    const char* p = std::strchr(letters, std::tolower(static_cast<unsigned char>(c)));
    return c && p ? static_cast<int>(p - letters) : -1;
}

// "0".."15" -> joint (and axis) n; "x".."w" -> axis, joint -1
void joint_or_axis(const std::string& name, const std::string& s, motion_command& c)
{
    if (s.size() == 1 && axis_index(s[0]) >= 0) {
        c.axis = axis_index(s[0]);
        c.joint = -1;
        return;
    }
    c.joint = integer(name, s);
    c.axis = c.joint;
}

int axis_arg(const std::string& name, const std::string& s)
{
    if (s.size() == 1 && axis_index(s[0]) >= 0)
        return axis_index(s[0]);
    return integer(name, s);
}

int spindle_opt(const std::string& name, const Args& a, size_t i)
{
    return i < a.size() ? integer(name, a[i]) : 0;
}

int on_off(const std::string& name, const std::string& s)
{
    if (s == "1" || s == "on" || s == "true")
        return 1;
    if (s == "0" || s == "off" || s == "false")
        return 0;
    throw ParseError{name + ": '" + s + "' is not 0/1/on/off"};
}

// the optional third word of dout/aout: "sync" or nothing
bool sync_word(const std::string& name, const Args& a)
{
    if (a.size() < 3)
        return false;
    if (a[2] != "sync")
        throw ParseError{name + ": '" + a[2] + "' is not 'sync'"};
    return true;
}

struct Entry {
    const char* name;
    int command;     // 0: not a plain command (action)
    int min_args;
    int max_args;
    const char* args;
    std::function<void(const Args&, MotcmdRequest&)> fill;
};

// a move: N coordinates (1..9) then VEL ACC
void move(const std::string& name, const Args& a, MotcmdRequest& r)
{
    size_t n = a.size() - 2;
    for (size_t i = 0; i < n; ++i)
        r.cmd.pos.v[i] = number(name, a[i]);
    r.cmd.vel = number(name, a[n]);
    r.cmd.ini_maxvel = r.cmd.vel;
    r.cmd.acc = number(name, a[n + 1]);
}

const std::vector<Entry>& table()
{
    static const std::vector<Entry> t = {
        {"status", 0, 0, 0, "", [](const Args&, MotcmdRequest& r) { r.action = MotcmdAction::Status; }},
        {"errors", 0, 0, 0, "", [](const Args&, MotcmdRequest& r) { r.action = MotcmdAction::Errors; }},
        {"wait-inpos", 0, 0, 1, "[SECONDS]", [](const Args& a, MotcmdRequest& r) {
             r.action = MotcmdAction::WaitInpos;
             if (!a.empty()) r.wait_s = number("wait-inpos", a[0]); }},
        {"wait-homed", 0, 0, 1, "[SECONDS]", [](const Args& a, MotcmdRequest& r) {
             r.action = MotcmdAction::WaitHomed;
             if (!a.empty()) r.wait_s = number("wait-homed", a[0]); }},
        {"wait-state", 0, 1, 2, "disabled|free|teleop|coord [SECONDS]", [](const Args& a, MotcmdRequest& r) {
             static const char* names[] = {"disabled", "free", "teleop", "coord"};
             r.action = MotcmdAction::WaitState;
             r.state = -1;
             for (int i = 0; i < 4; ++i)
                 if (a[0] == names[i]) r.state = i;
             if (r.state < 0) throw ParseError{"wait-state: '" + a[0] + "' is not disabled/free/teleop/coord"};
             if (a.size() > 1) r.wait_s = number("wait-state", a[1]); }},
        {"abort", MOTCMD_ABORT, 0, 0, "", nullptr},
        {"enable", MOTCMD_ENABLE, 0, 0, "", nullptr},
        {"disable", MOTCMD_DISABLE, 0, 0, "", nullptr},
        {"pause", MOTCMD_PAUSE, 0, 0, "", nullptr},
        {"resume", MOTCMD_RESUME, 0, 0, "", nullptr},
        {"step", MOTCMD_STEP, 0, 0, "", nullptr},
        {"free", MOTCMD_FREE, 0, 0, "", nullptr},
        {"teleop", MOTCMD_TELEOP, 0, 0, "", nullptr},
        {"coord", MOTCMD_COORD, 0, 0, "", nullptr},
        {"clear-probe", MOTCMD_CLEAR_PROBE_FLAGS, 0, 0, "", nullptr},
        {"jog-cont", MOTCMD_JOG_CONT, 2, 2, "JOINT|AXIS VEL", [](const Args& a, MotcmdRequest& r) {
             joint_or_axis("jog-cont", a[0], r.cmd);
             r.cmd.vel = number("jog-cont", a[1]); }},
        {"jog-incr", MOTCMD_JOG_INCR, 3, 3, "JOINT|AXIS DISTANCE VEL", [](const Args& a, MotcmdRequest& r) {
             joint_or_axis("jog-incr", a[0], r.cmd);
             r.cmd.offset = number("jog-incr", a[1]);
             r.cmd.vel = std::fabs(number("jog-incr", a[2])); }},
        {"jog-abs", MOTCMD_JOG_ABS, 3, 3, "JOINT|AXIS POSITION VEL", [](const Args& a, MotcmdRequest& r) {
             joint_or_axis("jog-abs", a[0], r.cmd);
             r.cmd.offset = number("jog-abs", a[1]);
             r.cmd.vel = std::fabs(number("jog-abs", a[2])); }},
        {"jog-abort", MOTCMD_JOG_ABORT, 1, 1, "JOINT|AXIS", [](const Args& a, MotcmdRequest& r) {
             joint_or_axis("jog-abort", a[0], r.cmd); }},
        {"home", MOTCMD_JOINT_HOME, 1, 1, "JOINT|all", [](const Args& a, MotcmdRequest& r) {
             r.cmd.joint = a[0] == "all" ? -1 : integer("home", a[0]); }},
        {"unhome", MOTCMD_JOINT_UNHOME, 1, 1, "JOINT|all|volatile", [](const Args& a, MotcmdRequest& r) {
             r.cmd.joint = a[0] == "all" ? -1 : a[0] == "volatile" ? -2 : integer("unhome", a[0]); }},
        {"activate", MOTCMD_JOINT_ACTIVATE, 1, 1, "JOINT", [](const Args& a, MotcmdRequest& r) {
             r.cmd.joint = integer("activate", a[0]); }},
        {"deactivate", MOTCMD_JOINT_DEACTIVATE, 1, 1, "JOINT", [](const Args& a, MotcmdRequest& r) {
             r.cmd.joint = integer("deactivate", a[0]); }},
        {"override-limits", MOTCMD_OVERRIDE_LIMITS, 1, 1, "JOINT|-1", [](const Args& a, MotcmdRequest& r) {
             r.cmd.joint = integer("override-limits", a[0]); }},
        {"line", MOTCMD_SET_LINE, 3, 11, "X [Y Z A B C U V W] VEL ACC", [](const Args& a, MotcmdRequest& r) {
             move("line", a, r);
             r.cmd.motion_type = MOTION_TYPE_FEED; }},
        {"rapid", MOTCMD_SET_LINE, 3, 11, "X [Y Z A B C U V W] VEL ACC", [](const Args& a, MotcmdRequest& r) {
             move("rapid", a, r);
             r.cmd.motion_type = MOTION_TYPE_TRAVERSE; }},
        {"probe", MOTCMD_PROBE, 4, 12, "TYPE X [Y Z ...] VEL ACC", [](const Args& a, MotcmdRequest& r) {
             r.cmd.probe_type = integer("probe", a[0]);
             move("probe", Args(a.begin() + 1, a.end()), r);
             r.cmd.motion_type = MOTION_TYPE_PROBING; }},
        {"arc", MOTCMD_SET_CIRCLE, 12, 12, "X Y Z CX CY CZ NX NY NZ TURN VEL ACC", [](const Args& a, MotcmdRequest& r) {
             for (int i = 0; i < 3; ++i) {
                 r.cmd.pos.v[i] = number("arc", a[i]);
                 r.cmd.center[i] = number("arc", a[3 + i]);
                 r.cmd.normal[i] = number("arc", a[6 + i]);
             }
             r.cmd.turn = integer("arc", a[9]);
             r.cmd.vel = number("arc", a[10]);
             r.cmd.ini_maxvel = r.cmd.vel;
             r.cmd.acc = number("arc", a[11]);
             r.cmd.motion_type = MOTION_TYPE_ARC; }},
        {"term-cond", MOTCMD_SET_TERM_COND, 1, 2, "stop|exact|blend [TOLERANCE]", [](const Args& a, MotcmdRequest& r) {
             if (a[0] == "stop") r.cmd.termCond = MOTION_TERM_STOP;
             else if (a[0] == "exact") r.cmd.termCond = MOTION_TERM_EXACT;
             else if (a[0] == "blend") r.cmd.termCond = MOTION_TERM_PARABOLIC;
             else throw ParseError{"term-cond: '" + a[0] + "' is not stop/exact/blend"};
             if (a.size() > 1) r.cmd.tolerance = number("term-cond", a[1]); }},
        {"feed-scale", MOTCMD_FEED_SCALE, 1, 1, "SCALE", [](const Args& a, MotcmdRequest& r) {
             r.cmd.scale = number("feed-scale", a[0]); }},
        {"rapid-scale", MOTCMD_RAPID_SCALE, 1, 1, "SCALE", [](const Args& a, MotcmdRequest& r) {
             r.cmd.scale = number("rapid-scale", a[0]); }},
        {"spindle-scale", MOTCMD_SPINDLE_SCALE, 1, 2, "SCALE [SPINDLE]", [](const Args& a, MotcmdRequest& r) {
             r.cmd.scale = number("spindle-scale", a[0]);
             r.cmd.spindle = spindle_opt("spindle-scale", a, 1); }},
        {"fs-enable", MOTCMD_FS_ENABLE, 1, 1, "0|1", [](const Args& a, MotcmdRequest& r) { r.cmd.mode = on_off("fs-enable", a[0]); }},
        {"ss-enable", MOTCMD_SS_ENABLE, 1, 1, "0|1", [](const Args& a, MotcmdRequest& r) { r.cmd.mode = on_off("ss-enable", a[0]); }},
        {"fh-enable", MOTCMD_FH_ENABLE, 1, 1, "0|1", [](const Args& a, MotcmdRequest& r) { r.cmd.mode = on_off("fh-enable", a[0]); }},
        {"af-enable", MOTCMD_AF_ENABLE, 1, 1, "0|1", [](const Args& a, MotcmdRequest& r) { r.cmd.mode = on_off("af-enable", a[0]); }},
        {"set-vel", MOTCMD_SET_VEL, 1, 1, "VEL", [](const Args& a, MotcmdRequest& r) {
             r.cmd.vel = number("set-vel", a[0]); r.cmd.ini_maxvel = r.cmd.vel; }},
        {"set-vel-limit", MOTCMD_SET_VEL_LIMIT, 1, 1, "VEL", [](const Args& a, MotcmdRequest& r) { r.cmd.vel = number("set-vel-limit", a[0]); }},
        {"set-acc", MOTCMD_SET_ACC, 1, 1, "ACC", [](const Args& a, MotcmdRequest& r) { r.cmd.acc = number("set-acc", a[0]); }},
        {"set-max-feed-override", MOTCMD_SET_MAX_FEED_OVERRIDE, 1, 1, "SCALE", [](const Args& a, MotcmdRequest& r) {
             r.cmd.scale = number("set-max-feed-override", a[0]); }},
        {"set-joint-limits", MOTCMD_SET_JOINT_POSITION_LIMITS, 3, 3, "JOINT MIN MAX", [](const Args& a, MotcmdRequest& r) {
             r.cmd.joint = integer("set-joint-limits", a[0]);
             r.cmd.minLimit = number("set-joint-limits", a[1]);
             r.cmd.maxLimit = number("set-joint-limits", a[2]); }},
        {"set-joint-vel", MOTCMD_SET_JOINT_VEL_LIMIT, 2, 2, "JOINT VEL", [](const Args& a, MotcmdRequest& r) {
             r.cmd.joint = integer("set-joint-vel", a[0]); r.cmd.value = number("set-joint-vel", a[1]); }},
        {"set-joint-acc", MOTCMD_SET_JOINT_ACC_LIMIT, 2, 2, "JOINT ACC", [](const Args& a, MotcmdRequest& r) {
             r.cmd.joint = integer("set-joint-acc", a[0]); r.cmd.value = number("set-joint-acc", a[1]); }},
        {"set-joint-backlash", MOTCMD_SET_JOINT_BACKLASH, 2, 2, "JOINT BACKLASH", [](const Args& a, MotcmdRequest& r) {
             r.cmd.joint = integer("set-joint-backlash", a[0]); r.cmd.value = number("set-joint-backlash", a[1]); }},
        {"set-joint-ferror", MOTCMD_SET_JOINT_MAX_FERROR, 2, 2, "JOINT FERROR", [](const Args& a, MotcmdRequest& r) {
             r.cmd.joint = integer("set-joint-ferror", a[0]); r.cmd.value = number("set-joint-ferror", a[1]); }},
        {"set-joint-min-ferror", MOTCMD_SET_JOINT_MIN_FERROR, 2, 2, "JOINT MIN_FERROR", [](const Args& a, MotcmdRequest& r) {
             r.cmd.joint = integer("set-joint-min-ferror", a[0]); r.cmd.value = number("set-joint-min-ferror", a[1]); }},
        {"set-joint-motor-offset", MOTCMD_SET_JOINT_MOTOR_OFFSET, 2, 2, "JOINT OFFSET", [](const Args& a, MotcmdRequest& r) {
             r.cmd.joint = integer("set-joint-motor-offset", a[0]); r.cmd.offset = number("set-joint-motor-offset", a[1]); }},
        {"set-joint-homing", MOTCMD_SET_JOINT_HOMING_PARAMS, 8, 9,
         "JOINT HOME_OFFSET HOME FINAL_VEL SEARCH_VEL LATCH_VEL FLAGS SEQUENCE [VOLATILE]", [](const Args& a, MotcmdRequest& r) {
             const std::string n = "set-joint-homing";
             r.cmd.joint = integer(n, a[0]);
             r.cmd.offset = number(n, a[1]);
             r.cmd.home = number(n, a[2]);
             r.cmd.home_final_vel = number(n, a[3]);
             r.cmd.search_vel = number(n, a[4]);
             r.cmd.latch_vel = number(n, a[5]);
             r.cmd.flags = integer(n, a[6]);
             r.cmd.home_sequence = integer(n, a[7]);
             r.cmd.volatile_home = a.size() > 8 ? integer(n, a[8]) : 0; }},
        {"set-joint-comp", MOTCMD_SET_JOINT_COMP, 4, 4, "JOINT NOMINAL FWD_TRIM REV_TRIM", [](const Args& a, MotcmdRequest& r) {
             r.cmd.joint = integer("set-joint-comp", a[0]);
             r.cmd.comp_nominal = number("set-joint-comp", a[1]);
             r.cmd.comp_forward = number("set-joint-comp", a[2]);
             r.cmd.comp_reverse = number("set-joint-comp", a[3]); }},
        {"comp-file", 0, 3, 3, "JOINT FILE TYPE", [](const Args& a, MotcmdRequest& r) {
             r.action = MotcmdAction::CompFile;
             r.cmd.command = MOTCMD_SET_JOINT_COMP;
             r.cmd.joint = integer("comp-file", a[0]);
             r.file = a[1];
             r.comp_type = integer("comp-file", a[2]);
             if (r.comp_type != 0 && r.comp_type != 1)
                 throw ParseError{"comp-file: type " + a[2] + " is not 0 or 1"}; }},
        {"set-axis-limits", MOTCMD_SET_AXIS_POSITION_LIMITS, 3, 3, "AXIS MIN MAX", [](const Args& a, MotcmdRequest& r) {
             r.cmd.axis = axis_arg("set-axis-limits", a[0]);
             r.cmd.minLimit = number("set-axis-limits", a[1]);
             r.cmd.maxLimit = number("set-axis-limits", a[2]); }},
        {"set-axis-vel", MOTCMD_SET_AXIS_VEL_LIMIT, 2, 2, "AXIS VEL", [](const Args& a, MotcmdRequest& r) {
             r.cmd.axis = axis_arg("set-axis-vel", a[0]); r.cmd.value = number("set-axis-vel", a[1]); }},
        {"set-axis-eoffset-limits", MOTCMD_SET_AXIS_EXT_OFFSET_LIMITS, 3, 3, "AXIS VEL ACC", [](const Args& a, MotcmdRequest& r) {
             r.cmd.axis = axis_arg("set-axis-eoffset-limits", a[0]);
             r.cmd.vel = number("set-axis-eoffset-limits", a[1]);
             r.cmd.acc = number("set-axis-eoffset-limits", a[2]); }},
        {"set-axis-acc", MOTCMD_SET_AXIS_ACC_LIMIT, 2, 2, "AXIS ACC", [](const Args& a, MotcmdRequest& r) {
             r.cmd.axis = axis_arg("set-axis-acc", a[0]); r.cmd.value = number("set-axis-acc", a[1]); }},
        // sync: with the next queued move's start, and END (if given) at its end
        {"dout", MOTCMD_SET_DOUT, 2, 4, "INDEX 0|1 [sync [END]]", [](const Args& a, MotcmdRequest& r) {
             r.cmd.out = integer("dout", a[0]);
             r.cmd.start = r.cmd.end = on_off("dout", a[1]);
             r.cmd.now = !sync_word("dout", a);
             if (a.size() > 3) r.cmd.end = on_off("dout", a[3]); }},
        {"aout", MOTCMD_SET_AOUT, 2, 4, "INDEX VALUE [sync [END]]", [](const Args& a, MotcmdRequest& r) {
             r.cmd.out = integer("aout", a[0]);
             r.cmd.aout_start = r.cmd.aout_end = number("aout", a[1]);
             r.cmd.now = !sync_word("aout", a);
             if (a.size() > 3) r.cmd.aout_end = number("aout", a[3]); }},
        {"spindle-on", MOTCMD_SPINDLE_ON, 1, 5, "RPM [SPINDLE [CSS_FACTOR XOFFSET]] [wait]", [](const Args& all, MotcmdRequest& r) {
             // 'wait': the next feed move waits for spindle.S.at-speed
             Args a = all;
             if (a.size() > 1 && a.back() == "wait") { r.cmd.wait_for_at_speed = 1; a.pop_back(); }
             if (a.size() > 4) throw ParseError{"spindle-on: '" + a[4] + "' is not 'wait'"};
             r.cmd.vel = number("spindle-on", a[0]);
             r.cmd.spindle = spindle_opt("spindle-on", a, 1);
             if (a.size() == 3) throw ParseError{"spindle-on: CSS_FACTOR needs XOFFSET"};
             if (a.size() > 3) {
                 r.cmd.css_factor = number("spindle-on", a[2]);
                 r.cmd.xoffset = number("spindle-on", a[3]);
             } }},
        {"spindle-off", MOTCMD_SPINDLE_OFF, 0, 1, "[SPINDLE]", [](const Args& a, MotcmdRequest& r) {
             r.cmd.spindle = spindle_opt("spindle-off", a, 0); }},
        {"spindle-increase", MOTCMD_SPINDLE_INCREASE, 0, 1, "[SPINDLE]", [](const Args& a, MotcmdRequest& r) {
             r.cmd.spindle = spindle_opt("spindle-increase", a, 0); }},
        {"spindle-decrease", MOTCMD_SPINDLE_DECREASE, 0, 1, "[SPINDLE]", [](const Args& a, MotcmdRequest& r) {
             r.cmd.spindle = spindle_opt("spindle-decrease", a, 0); }},
        {"spindle-brake", MOTCMD_SPINDLE_BRAKE_ENGAGE, 1, 2, "on|off [SPINDLE]", [](const Args& a, MotcmdRequest& r) {
             r.cmd.command = on_off("spindle-brake", a[0]) ? MOTCMD_SPINDLE_BRAKE_ENGAGE : MOTCMD_SPINDLE_BRAKE_RELEASE;
             r.cmd.spindle = spindle_opt("spindle-brake", a, 1); }},
        {"spindle-orient", MOTCMD_SPINDLE_ORIENT, 2, 3, "ANGLE MODE [SPINDLE]", [](const Args& a, MotcmdRequest& r) {
             r.cmd.orientation = number("spindle-orient", a[0]);
             r.cmd.mode = integer("spindle-orient", a[1]);
             r.cmd.spindle = spindle_opt("spindle-orient", a, 2); }},
        {"spindle-params", MOTCMD_SET_SPINDLE_PARAMS, 6, 6, "SPINDLE MIN_FWD MAX_FWD MIN_REV MAX_REV INCREMENT", [](const Args& a, MotcmdRequest& r) {
             r.cmd.spindle = integer("spindle-params", a[0]);
             for (int i = 0; i < 5; ++i)
                 r.cmd.spindle_params[i] = number("spindle-params", a[1 + i]); }},
        {"spindle-sync", MOTCMD_SET_SPINDLESYNC, 1, 3, "UNITS_PER_REV [velocity] [SPINDLE]", [](const Args& a, MotcmdRequest& r) {
             r.cmd.spindlesync = number("spindle-sync", a[0]);
             size_t i = 1;
             if (a.size() > 1 && a[1] == "velocity") { r.cmd.flags = 1; i = 2; }
             r.cmd.spindle = spindle_opt("spindle-sync", a, i); }},
        {"tool-offset", MOTCMD_SET_OFFSET, 1, 9, "X [Y Z A B C U V W]", [](const Args& a, MotcmdRequest& r) {
             for (size_t i = 0; i < a.size(); ++i)
                 r.cmd.pos.v[i] = number("tool-offset", a[i]); }},
        {"raw", 0, 1, 2, "COMMAND_NUMBER [JOINT]", [](const Args& a, MotcmdRequest& r) {
             r.cmd.command = integer("raw", a[0]);
             r.cmd.joint = a.size() > 1 ? integer("raw", a[1]) : 0; }},
    };
    return t;
}

}  // namespace

Result<MotcmdRequest> motcmd_parse(const std::vector<std::string>& words)
{
    if (words.empty())
        return Error{-EINVAL, "no command given (motcmd --help lists them)"};
    for (const Entry& e : table()) {
        if (words[0] != e.name)
            continue;
        Args args(words.begin() + 1, words.end());
        if (static_cast<int>(args.size()) < e.min_args || static_cast<int>(args.size()) > e.max_args)
            return Error{-EINVAL, std::string(e.name) + ": usage: " + e.name +
                                      (*e.args ? " " : "") + e.args};
        MotcmdRequest r;
        r.cmd.command = e.command;
        r.cmd.axis = -1;
        r.cmd.spindle = 0;
        r.cmd.id = 0;
        try {
            if (e.fill)
                e.fill(args, r);
        } catch (const ParseError& p) {
            return Error{-EINVAL, p.message};
        }
        return r;
    }
    return Error{-EINVAL, "unknown command '" + words[0] + "' (motcmd --help lists them)"};
}

bool motcmd_comp_line(const std::string& line, int type, double* nominal, double* fwd, double* rev)
{
    std::istringstream in(line);
    double n, a, b;
    std::string extra;
    if (!(in >> n >> a >> b) || (in >> extra) || !std::isfinite(n) || !std::isfinite(a) ||
        !std::isfinite(b))
        return false;
    *nominal = n;
    if (type == 0) {  // actual positions approached forward / backward -> trims
        *fwd = n - a;
        *rev = n - b;
    } else {
        *fwd = a;
        *rev = b;
    }
    return true;
}

const char* motcmd_usage()
{
    static std::string text = [] {
        std::string s =
            "usage: motcmd [--key N] [--timeout MS] [--id LINE] [--force-number N] COMMAND [ARGS...]\n"
            "       motcmd [options] -f FILE     (one command per line, # comments)\n"
            "Sends one command to motmod's command channel, prints its result; 'status'\n"
            "prints motion's status. Exit: 0 done, 1 refused by motion / wait timed out,\n"
            "2 bad usage, 3 no channel (motmod not loaded, timeout, another writer).\n"
            "Commands:\n";
        for (const Entry& e : table())
            s += std::string("  ") + e.name + (*e.args ? " " : "") + e.args + "\n";
        return s;
    }();
    return text.c_str();
}

}  // namespace hal
