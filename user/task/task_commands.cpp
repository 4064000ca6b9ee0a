// SPDX-License-Identifier: GPL-2.0-or-later
// task_commands.cpp - what task does with each bus command (docs/bus.md lists them)
// and with the io client's lines.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sys/stat.h>

#include "hal/numbers.hpp"
#include "task.hpp"

namespace hal::task {


static int on_off(const std::string& s)
{
    std::string u;
    for (char c : s)
        u += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (u == "ON" || u == "1")
        return 1;
    if (u == "OFF" || u == "0")
        return 0;
    return -1;
}

void Task::on_connect(int client, bus::Role role)
{
    if (role == bus::Role::Io) {
        io_client_ = client;
        io_.connected = true;
        io_estop_.connected();
        io_.tools_expected = 0;
        // a fresh io knows nothing of the machine: bring it to the requested state
        io_send({"INIT"});
        if (requested_state_ != TaskState::ESTOP && requested_state_ != TaskState::OFF)
            io_send({"ESTOP_OFF"});
        else
            io_send({"ESTOP_ON"});
    }
}

void Task::on_disconnect(int client, bus::Role role)
{
    if (role == bus::Role::Io && client == io_client_) {
        io_client_ = -1;
        io_.connected = false;
        io_estop_.disconnected();
        io_wait_until_ = Clock::now() + std::chrono::seconds(5);
        // io commands in flight will not be answered
        for (long s = std::max(1L, io_serial_ - 63); s <= io_serial_; ++s)
            if (!io_done_.count(s))
                io_done_[s] = "iocontrol disconnected";
    }
    // a client's waiting commands are forgotten with it
    for (size_t i = 0; i < waiters_.size();)
        if (waiters_[i].client == client)
            waiters_.erase(waiters_.begin() + static_cast<long>(i));
        else
            ++i;
    for (auto it = mdi_queue_.begin(); it != mdi_queue_.end();)
        it = it->client == client ? mdi_queue_.erase(it) : it + 1;
}

void Task::on_io_line(int client, const std::string& line)
{
    if (client != io_client_)
        return;   // a link that is being replaced
    if (io_.tools_expected > 0) {
        io_.tools_in.push_back(line);
        if (--io_.tools_expected == 0)
            io_.tools = std::move(io_.tools_in);
        return;
    }
    auto w = bus::split_words(line, 4);
    if (w.empty())
        return;
    if (w[0] == "IOACK" && w.size() >= 3) {
        long n = 0;
        if (!parse_integer(w[1], n))
            return;
        if (w[2] == "DONE")
            io_done_[n] = "";
        else
            io_done_[n] = w.size() > 3 ? w[3] : "failed";
        // anything not taken within a while is dropped (bounded map)
        while (io_done_.size() > 256)
            io_done_.erase(io_done_.begin());
    } else if (w[0] == "IOSTAT") {
        auto kvs = parse_iostat(line.substr(6));
        if (auto e = kvs.find("estop"); e != kvs.end()) {
            auto a = kvs.find("ack");
            io_estop_.report(e->second != 0, a == kvs.end() ? 0 : a->second);
        }
        for (const auto& [k, v] : kvs) {
            if (k == "mist") io_.mist = v != 0;
            else if (k == "flood") io_.flood = v != 0;
            else if (k == "lube") io_.lube = v != 0;
            else if (k == "lube_level") io_.lube_level = v != 0;
            else if (k == "tool") io_.tool = static_cast<int>(v);
            else if (k == "pocket_prepped") io_.pocket_prepped = static_cast<int>(v);
            else if (k == "prep_tool") io_.prep_tool = static_cast<int>(v);
            else if (k == "from_pocket") io_.from_pocket = static_cast<int>(v);
        }
    } else if (w[0] == "IOTOOLS" && w.size() >= 2) {
        long n = 0;
        if (!parse_integer(w[1], n) || n < 0 || n > 100000)
            return;
        io_.tools_in.clear();
        io_.tools_expected = static_cast<size_t>(n);
        if (n == 0)
            io_.tools.clear();
    }
}

void Task::on_command(int client, const bus::Request& r)
{
    if (r.verb == "STATUS") {
        server_->send_status(client, r.serial, status_lines());
        return;
    }
    Situation s;
    s.state = state_;
    s.mode = mode_;
    s.interp = interp_state_;
    s.all_homed = all_homed();
    s.no_force_homing = cfg_.no_force_homing;
    s.program_open = program_open_;
    s.busy = in_interp_;
    std::string err = check_command(r.verb, s);
    if (err.empty() && !motion_ready_ && r.verb != "PING" && r.verb != "STATE")
        err = r.verb + ": motion is not running yet (threads not started?)";
    if (!err.empty()) {
        server_->reply(client, r.serial, "ERROR " + err);
        return;
    }
    server_->reply(client, r.serial, "RECEIVED");
    if (r.verb == "PING") {
        server_->reply(client, r.serial, "DONE");
        return;
    }
    if (r.verb == "STATE")
        err = cmd_state(client, r);
    else if (r.verb == "MODE")
        err = cmd_mode(r);
    else if (r.verb == "MDI" || r.verb == "OPEN" || r.verb == "CLOSE" || r.verb == "RUN" || r.verb == "PAUSE" ||
             r.verb == "RESUME" || r.verb == "STEP" || r.verb == "ABORT" || r.verb == "PLAN_INIT")
        err = cmd_program(client, r);
    else if (r.verb == "HOME" || r.verb == "UNHOME" || r.verb.rfind("JOG_", 0) == 0 || r.verb == "TELEOP" ||
             r.verb == "OVERRIDE_LIMITS" || r.verb == "SPINDLE" || r.verb == "BRAKE")
        err = cmd_manual(r);
    else if (r.verb == "MIST" || r.verb == "FLOOD" || r.verb == "LUBE" || r.verb == "TOOL_OFFSET" ||
             r.verb == "LOAD_TOOL_TABLE")
        err = cmd_io(client, r);
    else
        err = cmd_setting(r);
    if (err == "*")
        return;   // finishes later (a waiter or the MDI queue replies)
    server_->reply(client, r.serial, err.empty() ? "DONE" : "ERROR " + err);
}

std::string Task::cmd_state(int client, const bus::Request& r)
{
    auto want = parse_state(r.args[0]);
    if (!want)
        return "STATE: '" + bus::sanitize(r.args[0], 40) + "' is not ESTOP, ESTOP_RESET, OFF or ON";
    if (!motion_ready_ && *want == TaskState::ON)
        return "STATE: motion is not running yet";
    // iocontrol starts before task and connects within its retry period (200 ms): a
    // reset sent right after start-up waits for it (on_connect brings a fresh io to the
    // requested state) instead of failing
    bool io_coming = *want == TaskState::ESTOP_RESET && !io_.connected && Clock::now() < io_wait_until_;
    std::string err = io_coming ? "" : check_state_request(*want, state_, io_.connected, io_estop_.estop());
    if (!err.empty())
        return "STATE " + std::string(state_name(*want)) + ": " + err;
    set_state(*want);
    if (*want == TaskState::ESTOP || *want == TaskState::OFF) {
        // done once the status shows it (the next state update: ESTOP_ON latches
        // task's estop at once, motion disables within a servo period), so a client
        // that reads the status after DONE sees the new state
        TaskState target = *want;
        auto deadline = state_deadline();
        waiters_.push_back({client, r.serial, [this, target, deadline](std::string& e) {
                                if (target == TaskState::ESTOP ? state_ == TaskState::ESTOP
                                                               : state_ != TaskState::ON)
                                    return 1;
                                if (Clock::now() < deadline)
                                    return 0;
                                e = target == TaskState::ESTOP ? "STATE ESTOP: the estop did not take effect"
                                                               : "STATE OFF: motion did not disable";
                                return -1;
                            }});
        return "*";
    }
    if (*want == TaskState::ON) {
        // done once motion reports itself enabled (motion.enable FALSE: it never does)
        auto deadline = state_deadline();
        waiters_.push_back({client, r.serial, [this, deadline](std::string& e) {
                                if (motion_enabled())
                                    return 1;
                                if (Clock::now() < deadline && requested_state_ == TaskState::ON)
                                    return 0;
                                e = "STATE ON: motion did not enable (is motion.enable TRUE?)";
                                requested_state_ = state_;
                                return -1;
                            }});
        return "*";
    }
    if (*want == TaskState::ESTOP_RESET) {
        auto deadline = std::max(Clock::now(), io_wait_until_) + std::chrono::seconds(2);
        waiters_.push_back({client, r.serial, [this, deadline](std::string& e) {
                                // a report from after the ESTOP_OFF (io_estop.hpp)
                                if (io_estop_.settled() && !io_estop_.estop())
                                    return 1;
                                if (Clock::now() < deadline)
                                    return 0;
                                e = io_.connected ? "STATE ESTOP_RESET: estop is still active (iocontrol.0.emc-enable-in FALSE)"
                                                  : "STATE ESTOP_RESET: cannot reset estop: iocontrol is not connected";
                                return -1;
                            }});
        return "*";
    }
    return "";
}

std::string Task::cmd_mode(const bus::Request& r)
{
    auto want = parse_mode(r.args[0]);
    if (!want)
        return "MODE: '" + bus::sanitize(r.args[0], 40) + "' is not MANUAL, AUTO or MDI";
    std::string err = check_mode_change(mode_, *want, interp_state_, mst_.jogging_active != 0);
    if (!err.empty())
        return err;
    if (*want == mode_)
        return "";
    if (*want != TaskMode::MANUAL || mode_ != TaskMode::MANUAL) {
        // leaving or entering program modes: a clean start for the interpreter
        abort_task("");
        refresh_interp_state();
    }
    mode_ = *want;
    last_mode_send_ = {};
    return "";
}

std::string Task::cmd_program(int client, const bus::Request& r)
{
    const std::string& v = r.verb;
    if (v == "MDI") {
        if (static_cast<int>(mdi_queue_.size()) >= cfg_.mdi_queued)
            return "MDI: queue full (" + std::to_string(cfg_.mdi_queued) + " commands waiting)";
        mdi_queue_.push_back({client, r.serial, r.args[0]});
        return "*";
    }
    if (v == "OPEN") {
        struct stat st;
        if (stat(r.args[0].c_str(), &st) != 0 || !S_ISREG(st.st_mode))
            return "OPEN: cannot open '" + bus::sanitize(r.args[0]) + "': no such file";
        in_interp_ = true;
        bool ok = interp_->open(r.args[0]);
        in_interp_ = false;
        if (!ok) {
            std::string e = interp_->error().to_string();
            error_all(e);
            program_open_ = false;
            return "OPEN: " + e;
        }
        program_file_ = r.args[0];
        program_open_ = true;
        return "";
    }
    if (v == "CLOSE") {
        interp_->reset();
        program_open_ = false;
        program_file_.clear();
        return "";
    }
    if (v == "PLAN_INIT") {
        std::string e;
        interp_->reset();
        if (!init(e)) {
            error_all(e);
            return "PLAN_INIT: " + e;
        }
        return "";
    }
    if (v == "ABORT") {
        abort_task("");
        return "";
    }
    if (v == "PAUSE") {
        if (interp_state_ == InterpState::IDLE)
            return "";
        send_motion(mcmd(MOTCMD_PAUSE), nullptr);
        paused_ = true;
        return "";
    }
    if (v == "RESUME") {
        if (!paused_ && !step_mode_)
            return "";
        step_mode_ = step_hold_ = false;
        paused_ = false;
        send_motion(mcmd(MOTCMD_RESUME), nullptr);
        return "";
    }
    // RUN [line] and STEP
    long start = 0;
    if (v == "RUN" && !r.args.empty() && (!parse_integer(r.args[0], start) || start < 0))
        return "RUN: '" + bus::sanitize(r.args[0], 40) + "' is not a line number";
    if (v == "STEP" && interp_state_ != InterpState::IDLE) {
        // one more block: from a pause or from the previous step
        if (paused_) {
            paused_ = false;
            send_motion(mcmd(MOTCMD_RESUME), nullptr);
        }
        step_mode_ = true;
        step_hold_ = false;
        return "";
    }
    in_interp_ = true;
    bool ok = interp_->open(program_file_);   // from its start again
    in_interp_ = false;
    if (!ok) {
        std::string e = interp_->error().to_string();
        error_all(e);
        return v + ": " + e;
    }
    synch_interp_if_idle();
    if (start > 1) {
        // blocks before the start line set the modal state but move nothing
        canon_->set_skip(true);
        while (interp_->line() < start - 1) {
            in_interp_ = true;
            rs274::Status s = interp_->step();
            in_interp_ = false;
            if (s != rs274::Status::OK) {
                canon_->set_skip(false);
                std::string e = s == rs274::Status::END ? "the program ends before line " + std::to_string(start)
                                                        : interp_->error().to_string();
                if (s == rs274::Status::ERROR)
                    error_all(e);
                interp_->reset();
                return v + ": " + e;
            }
        }
        canon_->set_skip(false);
        canon_->queue().clear();
    }
    reading_ = true;
    program_running_ = true;
    paused_ = false;
    step_mode_ = v == "STEP";
    step_hold_ = false;
    return "";
}

std::string Task::cmd_manual(const bus::Request& r)
{
    const std::string& v = r.verb;
    std::string err;
    // a joint number (-1 all) or an axis letter (teleop jogs): 1 joint, 2 axis, 0 neither
    auto joint_arg = [&](const std::string& s, motion_command& c) -> int {
        if (s.size() == 1 && ini::axis_index(s[0]) >= 0) {
            c.axis = ini::axis_index(s[0]);
            c.joint = -1;
            return 2;
        }
        long j = 0;
        if (!parse_integer(s, j) || j < -1 || j >= cfg_.joints)
            return 0;
        c.joint = static_cast<int>(j);
        c.axis = c.joint;
        return 1;
    };
    if (v == "HOME" || v == "UNHOME") {
        motion_command c = mcmd(v == "HOME" ? MOTCMD_JOINT_HOME : MOTCMD_JOINT_UNHOME);
        if (joint_arg(r.args[0], c) != 1)
            return v + ": '" + bus::sanitize(r.args[0], 40) + "' is not a joint number (or -1 for all)";
        if (v == "HOME" && mst_.motion_state != MOTION_FREE)
            send_motion(mcmd(MOTCMD_FREE), nullptr);   // homing runs in joint mode
        return send_motion(c, &err) ? "" : v + ": " + err;
    }
    if (v == "TELEOP") {
        int on = on_off(r.args[0]);
        if (on < 0)
            return "TELEOP: '" + bus::sanitize(r.args[0], 40) + "' is not 0 or 1";
        teleop_wanted_ = on == 1;
        last_mode_send_ = {};
        return "";
    }
    if (v == "OVERRIDE_LIMITS") {
        motion_command c = mcmd(MOTCMD_OVERRIDE_LIMITS);
        if (joint_arg(r.args[0], c) != 1)
            return v + ": '" + bus::sanitize(r.args[0], 40) + "' is not a joint number";
        return send_motion(c, &err) ? "" : v + ": " + err;
    }
    if (v.rfind("JOG_", 0) == 0) {
        motion_command c = mcmd(v == "JOG_CONT"   ? MOTCMD_JOG_CONT
                                : v == "JOG_INCR" ? MOTCMD_JOG_INCR
                                : v == "JOG_ABS"  ? MOTCMD_JOG_ABS
                                                  : MOTCMD_JOG_ABORT);
        int kind = joint_arg(r.args[0], c);
        if (kind == 0 || (kind == 1 && c.joint < 0))
            return v + ": '" + bus::sanitize(r.args[0], 40) + "' is not a joint number or axis letter";
        if (kind == 2 && mst_.motion_state != MOTION_TELEOP && v != "JOG_STOP")
            return v + ": axis jogs need teleop mode (all joints homed)";
        if (kind == 1 && mst_.motion_state == MOTION_TELEOP && v != "JOG_STOP")
            return v + ": joint jogs need joint mode (TELEOP 0)";
        if (v != "JOG_STOP") {
            double vel = 0;
            if (!parse_finite(r.args[1], vel))
                return v + ": '" + bus::sanitize(r.args[1], 40) + "' is not a velocity";
            c.vel = v == "JOG_CONT" ? vel : std::fabs(vel);
            if (v != "JOG_CONT") {
                double x = 0;
                if (!parse_finite(r.args[2], x))
                    return v + ": '" + bus::sanitize(r.args[2], 40) + "' is not a number";
                c.offset = v == "JOG_INCR" && vel < 0 ? -std::fabs(x) : x;
            }
        }
        return send_motion(c, &err) ? "" : v + ": " + err;
    }
    if (v == "SPINDLE") {
        std::string d;
        for (char ch : r.args[0])
            d += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        double rpm = 0;
        long sp = -1;
        if (r.args.size() > 1 && !parse_finite(r.args[1], rpm))
            return "SPINDLE: '" + bus::sanitize(r.args[1], 40) + "' is not a speed";
        if (r.args.size() > 2 && (!parse_integer(r.args[2], sp) || sp < -1 || sp >= cfg_.spindles))
            return "SPINDLE: '" + bus::sanitize(r.args[2], 40) + "' is not a spindle number";
        if (cfg_.spindles == 0)
            return "SPINDLE: no spindles configured ([TRAJ]SPINDLES = 0)";
        motion_command c = mcmd(MOTCMD_SPINDLE_ON);
        c.spindle = static_cast<int>(sp);
        if (d == "FORWARD" || d == "REVERSE") {
            double speed = r.args.size() > 1 ? std::fabs(rpm) : std::fabs(canon_->view().speed[0]);
            if (speed == 0)
                speed = 500;   // emcrsh's rule: S0 -> 500 rpm
            c.vel = d == "REVERSE" ? -speed : speed;
        } else if (d == "OFF") {
            c.command = MOTCMD_SPINDLE_OFF;
        } else if (d == "INCREASE") {
            c.command = MOTCMD_SPINDLE_INCREASE;
        } else if (d == "DECREASE") {
            c.command = MOTCMD_SPINDLE_DECREASE;
        } else if (d == "CONSTANT") {
            return "";   // increase/decrease act once per command: nothing to stop
        } else {
            return "SPINDLE: '" + bus::sanitize(r.args[0], 40) +
                   "' is not FORWARD, REVERSE, OFF, INCREASE, DECREASE or CONSTANT";
        }
        return send_motion(c, &err) ? "" : "SPINDLE: " + err;
    }
    if (v == "BRAKE") {
        int on = on_off(r.args[0]);
        long sp = -1;
        if (on < 0)
            return "BRAKE: '" + bus::sanitize(r.args[0], 40) + "' is not ON or OFF";
        if (r.args.size() > 1 && (!parse_integer(r.args[1], sp) || sp < -1 || sp >= cfg_.spindles))
            return "BRAKE: '" + bus::sanitize(r.args[1], 40) + "' is not a spindle number";
        motion_command c = mcmd(on ? MOTCMD_SPINDLE_BRAKE_ENGAGE : MOTCMD_SPINDLE_BRAKE_RELEASE);
        c.spindle = static_cast<int>(sp);
        return send_motion(c, &err) ? "" : "BRAKE: " + err;
    }
    return v + ": unknown command";
}

std::string Task::cmd_io(int client, const bus::Request& r)
{
    const std::string& v = r.verb;
    std::vector<std::string> words;
    if (v == "MIST" || v == "FLOOD" || v == "LUBE") {
        int on = on_off(r.args[0]);
        if (on < 0)
            return v + ": '" + bus::sanitize(r.args[0], 40) + "' is not ON or OFF";
        words = {v, on ? "1" : "0"};
    } else if (v == "TOOL_OFFSET") {
        long tool = 0;
        double length = 0, diameter = 0;
        if (!parse_integer(r.args[0], tool) || tool < 0 || !parse_finite(r.args[1], length) || !parse_finite(r.args[2], diameter))
            return "TOOL_OFFSET: needs TOOL LENGTH DIAMETER (numbers)";
        // the tool keeps its pocket and its other fields (the interpreter has them)
        int pocket = 0;
        std::string prefix = "T" + std::to_string(tool) + " ";
        bool found = false;
        for (const std::string& l : io_.tools)
            if (l.rfind(prefix, 0) == 0) {
                size_t p = l.find(" P");
                pocket = p == std::string::npos ? 0 : std::atoi(l.c_str() + p + 2);
                found = true;
            }
        if (!found)
            return "TOOL_OFFSET: tool " + std::to_string(tool) + " is not in the tool table";
        words = {"TOOL_SET_OFFSET", std::to_string(tool), std::to_string(pocket), "0", "0",
                 std::to_string(length), "0", "0", "0", "0", "0", "0", std::to_string(diameter), "0", "0", "0"};
    } else {   // LOAD_TOOL_TABLE [file]
        words = {"LOAD_TOOL_TABLE"};
        if (!r.args.empty()) {
            if (r.args[0].find_first_of(" \t") != std::string::npos)
                return "LOAD_TOOL_TABLE: file names with blanks are not supported";
            words.push_back(r.args[0]);
        }
    }
    long n = io_send(words);
    std::string verb = v;
    waiters_.push_back({client, r.serial, [this, n, verb](std::string& e) {
                            std::string err;
                            int res = io_result(n, &err);
                            if (res < 0)
                                e = verb + ": iocontrol: " + err;
                            return res;
                        }});
    return "*";
}

std::string Task::cmd_setting(const bus::Request& r)
{
    const std::string& v = r.verb;
    std::string err;
    if (v == "OPTIONAL_STOP" || v == "BLOCK_DELETE") {
        int on = on_off(r.args[0]);
        if (on < 0)
            return v + ": '" + bus::sanitize(r.args[0], 40) + "' is not 0 or 1";
        if (v == "OPTIONAL_STOP") {
            optional_stop_ = on;
            interp_->set_optional_stop(on);
        } else {
            block_delete_ = on;
            interp_->set_block_delete(on);
        }
        return "";
    }
    if (v == "DEBUG") {
        long level = 0;
        if (!parse_integer(r.args[0], level))
            return "DEBUG: '" + bus::sanitize(r.args[0], 40) + "' is not a number";
        debug_ = static_cast<int>(level);
        motion_command c = mcmd(MOTCMD_SET_DEBUG);
        c.count = debug_;
        return send_motion(c, &err) ? "" : "DEBUG: " + err;
    }
    if (v == "PROBE_CLEAR")
        return send_motion(mcmd(MOTCMD_CLEAR_PROBE_FLAGS), &err) ? "" : "PROBE_CLEAR: " + err;
    double x = 0;
    if (!parse_finite(r.args[0], x) || x < 0)
        return v + ": '" + bus::sanitize(r.args[0], 40) + "' is not a number >= 0";
    if (v == "FEED_OVERRIDE" || v == "RAPID_OVERRIDE") {
        motion_command c = mcmd(v == "FEED_OVERRIDE" ? MOTCMD_FEED_SCALE : MOTCMD_RAPID_SCALE);
        c.scale = v == "FEED_OVERRIDE" ? std::min(x, cfg_.max_feed_override) : std::min(x, 1.0);
        return send_motion(c, &err) ? "" : v + ": " + err;
    }
    if (v == "SPINDLE_OVERRIDE") {
        long sp = -1;
        if (r.args.size() > 1 && (!parse_integer(r.args[1], sp) || sp < -1 || sp >= cfg_.spindles))
            return v + ": '" + bus::sanitize(r.args[1], 40) + "' is not a spindle number";
        motion_command c = mcmd(MOTCMD_SPINDLE_SCALE);
        c.spindle = static_cast<int>(sp);
        c.scale = x;
        return send_motion(c, &err) ? "" : v + ": " + err;
    }
    if (v == "MAX_VELOCITY") {
        motion_command c = mcmd(MOTCMD_SET_VEL_LIMIT);
        c.vel = std::min(x, cfg_.max_vel);
        return send_motion(c, &err) ? "" : v + ": " + err;
    }
    return v + ": unknown command";
}

}  // namespace hal::task
