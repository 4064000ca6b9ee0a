// SPDX-License-Identifier: GPL-2.0-or-later
// cmd_load.cpp - loadrt, unloadrt, loadusr, unloadusr, waitusr, unload (halcmd(1)).
// Realtime modules go to rtapi_app or the kernel (realtime.hpp); userspace components are
// programs we fork/exec and later SIGTERM by the pid their component records.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>

#include "commands.hpp"
#include "hal_query.h"
#include "realtime.hpp"
#include "session.hpp"
#include "snapshot.hpp"
#include "spawn/spawn.hpp"

namespace hal::halcmd {

namespace {

using namespace std::chrono_literals;
constexpr auto poll_interval = 20ms;
constexpr auto ready_timeout = 20s;      // loadusr -W: generous for slow (sanitizer) builds
constexpr auto kill_grace = 2s;          // loadusr -W timed out: SIGTERM, then SIGKILL
constexpr auto exit_timeout = 10s;       // unloadusr: SIGTERM to gone

// A zombie has exited: it answers kill(pid, 0) until its parent reaps it, and the
// parent of a component whose halcmd has exited is init, which may never reap it (some
// containers' init processes do not). /proc says which it is.
bool process_alive(int pid)
{
    if (pid <= 0 || (kill(pid, 0) != 0 && errno != EPERM))
        return false;
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!std::getline(stat, line))
        return true;                         // no /proc: kill() alone decides
    size_t close_paren = line.rfind(')');    // "PID (COMM) STATE ...": COMM may hold ')'
    if (close_paren == std::string::npos || close_paren + 2 >= line.size())
        return true;
    char state = line[close_paren + 2];
    return state != 'Z' && state != 'X';
}

// Userspace components matching name ("all": every one).
std::vector<hal_comp_info> user_comps(const std::string& name)
{
    std::vector<hal_comp_info> out;
    for (const hal_comp_info& c : take_snapshot(snap_comps).comps)
        if (!c.is_realtime && (name == "all" || name == c.name))
            out.push_back(c);
    return out;
}

std::string basename_of(const std::string& path)
{
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

struct LoadusrFlags {
    bool wait_ready = false;
    std::string wait_name;
    bool wait_exit = false;
    bool ignore_status = false;
    size_t program = 0;                  // index of the program in args
};

Result<LoadusrFlags> parse_loadusr_flags(Args args)
{
    LoadusrFlags f;
    size_t i = 0;
    for (; i < args.size() && args[i].size() > 1 && args[i][0] == '-'; i++) {
        const std::string& a = args[i];
        if (a == "-W") {
            f.wait_ready = true;
        } else if (a == "-Wn") {
            if (i + 1 >= args.size())
                return Error{-22, "loadusr: -Wn needs a component name"};
            f.wait_ready = true;
            f.wait_name = args[++i];
        } else if (a == "-w") {
            f.wait_exit = true;
        } else if (a == "-i") {
            f.ignore_status = true;
        } else {
            return Error{-22, "loadusr: unknown flag '" + a + "' (use -W, -Wn NAME, -w or -i)"};
        }
    }
    if (i >= args.size())
        return Error{-22, "loadusr: no program given"};
    f.program = i;
    if (f.wait_ready && f.wait_name.empty())
        f.wait_name = basename_of(args[i]);
    return f;
}

// fork/exec through PATH (spawn.hpp): "no such program" is our one error line
Result<int> spawn(const std::vector<std::string>& argv)
{
    auto pid = spawn_process(argv);
    if (!pid)
        return Error{pid.error().code, "loadusr: " + pid.error().message};
    return static_cast<int>(*pid);
}

std::string describe_status(int status)
{
    if (WIFEXITED(status))
        return "exited with status " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status))
        return std::string("was killed by signal ") + strsignal(WTERMSIG(status));
    return "stopped";
}

// loadusr -W's limit: HALCMD_READY_TIMEOUT (whole seconds, >= 1) when set, else 20 s.
Result<std::chrono::seconds> ready_limit()
{
    const char* env = std::getenv("HALCMD_READY_TIMEOUT");
    if (!env)
        return std::chrono::seconds(ready_timeout);
    char* end = nullptr;
    errno = 0;
    long v = std::strtol(env, &end, 10);
    if (errno || end == env || *end || v < 1 || v > 86400)
        return Error{-EINVAL, std::string("loadusr: HALCMD_READY_TIMEOUT='") + env +
                                  "' is not a number of seconds from 1 to 86400"};
    return std::chrono::seconds(v);
}

// A child that did not become ready in time must not stay behind half-started:
// SIGTERM, SIGKILL after a grace period, reaped, its components removed.
std::string stop_child(int pid)
{
    kill(pid, SIGTERM);
    auto deadline = std::chrono::steady_clock::now() + kill_grace;
    for (;;) {
        int status;
        if (waitpid(pid, &status, WNOHANG) == pid)
            break;
        if (std::chrono::steady_clock::now() > deadline) {
            kill(pid, SIGKILL);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            remove_dead_user_components();
            return "killed (pid " + std::to_string(pid) + ", SIGKILL: it ignored SIGTERM)";
        }
        std::this_thread::sleep_for(poll_interval);
    }
    remove_dead_user_components();
    return "stopped (pid " + std::to_string(pid) + ", SIGTERM)";
}

Result<void> wait_until_ready(int pid, const std::string& program, const std::string& name,
                              std::chrono::seconds limit)
{
    auto deadline = std::chrono::steady_clock::now() + limit;
    for (;;) {
        hal_comp_info c;
        if (hal_find_comp(name.c_str(), &c) == 0 && c.is_ready)
            return ok();
        int status;
        if (waitpid(pid, &status, WNOHANG) == pid) {
            remove_dead_user_components();     // what it made before dying must not stay behind
            return Error{-ECHILD, "loadusr: '" + program + "' " + describe_status(status) +
                                      " before component '" + name + "' became ready"};
        }
        if (std::chrono::steady_clock::now() > deadline)
            return Error{-ETIMEDOUT, "loadusr: waited " + std::to_string(limit.count()) +
                                         " s for component '" + name + "' to become ready; " +
                                         "'" + program + "' " + stop_child(pid)};
        std::this_thread::sleep_for(poll_interval);
    }
}

// What the module host would refuse only vaguely ("request is not a line of text")
// or misread (count=-1 is the components' "not given" value): issue 19, items 8, 9.
Result<void> check_loadrt_args(const std::string& module, const std::vector<std::string>& margs)
{
    for (size_t i = 0; i < margs.size(); ++i) {
        const std::string& a = margs[i];
        for (size_t k = 0; k < a.size(); ++k) {
            auto c = static_cast<unsigned char>(a[k]);
            if (c >= 0x20 && c != 0x7f)
                continue;
            char hex[8];
            std::snprintf(hex, sizeof(hex), "0x%02x", c);
            return Error{-EINVAL, "loadrt " + module + ": argument " + std::to_string(i + 1) + " ('" +
                                      a + "') contains " + (c ? std::string("control character ") + hex
                                                               : std::string("a NUL byte")) +
                                      " at position " + std::to_string(k + 1) +
                                      "; module arguments are plain text"};
        }
        auto eq = a.find('=');
        std::string name = a.substr(0, eq);
        std::string value = eq == std::string::npos ? "" : a.substr(eq + 1);
        if ((name == "count" || name == "num_chan") && value.size() > 1 && value[0] == '-' &&
            value.find_first_not_of("0123456789", 1) == std::string::npos)
            return Error{-EINVAL, "loadrt " + module + ": " + name + "=" + value +
                                      " is negative; give a number of instances of at least 1, "
                                      "or leave " + name + "= out for the default"};
    }
    return ok();
}

}  // namespace

void remove_dead_user_components()
{
    // A child of ours that died is a zombie until reaped, and a zombie still "exists".
    // (-w and -W wait for their own child within one command, so nothing is stolen.)
    while (waitpid(-1, nullptr, WNOHANG) > 0) {
    }
    hal_comps_remove_dead();
}

Result<void> cmd_loadrt(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_LOAD, "loadrt"); !r)
        return r;
    std::vector<std::string> margs(args.begin() + 1, args.end());
    if (auto r = check_loadrt_args(args[0], margs); !r)
        return r;
    Result<void> r = rt_load(args[0], margs);
    if (!r)
        return Error{r.error().code, r.error().message};
    s.info("Realtime module '" + args[0] + "' loaded");
    return ok();
}

Result<void> cmd_unloadrt(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_LOAD, "unloadrt"); !r)
        return r;
    Result<void> r = rt_unload(args[0]);
    if (!r)
        return Error{r.error().code, r.error().message};
    s.info(args[0] == "all" ? "All realtime modules unloaded" : "Realtime module '" + args[0] + "' unloaded");
    return ok();
}

Result<void> cmd_loadusr(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_LOAD, "loadusr"); !r)
        return r;
    auto flags = parse_loadusr_flags(args);
    if (!flags)
        return flags.error();
    std::vector<std::string> argv(args.begin() + static_cast<long>(flags->program), args.end());
    remove_dead_user_components();       // a crashed instance's name may be reused
    std::chrono::seconds limit{0};
    if (flags->wait_ready) {
        auto l = ready_limit();
        if (!l)
            return l.error();
        limit = *l;
        // The new program could not register this name anyway, and an existing ready
        // component would end the wait at once: refuse before starting anything.
        hal_comp_info c;
        if (hal_find_comp(flags->wait_name.c_str(), &c) == 0)
            return Error{-EEXIST, "loadusr: a component named '" + flags->wait_name + "' exists already" +
                                      (c.is_realtime ? std::string(" (realtime)")
                                                     : " (pid " + std::to_string(c.pid) + ")") +
                                      "; unload it first, or wait for another name with -Wn NAME"};
    }
    auto pid = spawn(argv);
    if (!pid)
        return pid.error();
    if (flags->wait_ready) {
        if (auto r = wait_until_ready(*pid, argv[0], flags->wait_name, limit); !r)
            return r;
    }
    if (flags->wait_exit) {
        int status = 0;
        while (waitpid(*pid, &status, 0) < 0 && errno == EINTR) {
        }
        bool success = WIFEXITED(status) && WEXITSTATUS(status) == 0;
        if (!success && !flags->ignore_status)
            return Error{-ECHILD, "loadusr: '" + argv[0] + "' " + describe_status(status)};
    }
    s.info("Program '" + argv[0] + "' started (pid " + std::to_string(*pid) + ")");
    return ok();
}

Result<void> unload_user_components(Session* s, const std::string& name)
{
    std::vector<hal_comp_info> comps = user_comps(name);
    if (comps.empty() && name != "all")
        return Error{-ENOENT, "unloadusr: no userspace component named '" + name + "'"};
    int self = static_cast<int>(getpid());
    for (const hal_comp_info& c : comps)
        if (c.pid != self && process_alive(c.pid))
            kill(c.pid, SIGTERM);
    auto deadline = std::chrono::steady_clock::now() + exit_timeout;
    for (const hal_comp_info& c : comps) {
        if (c.pid == self)
            continue;
        // Gone means the process has ended, not only its hal_exit(): a script that
        // runs unloadusr and then starts the program again must not meet the old one.
        // (Our own component, halcmd itself, only has to leave the HAL.)
        while (process_alive(c.pid)) {
            waitpid(c.pid, nullptr, WNOHANG);        // reap our own children (loadusr)
            if (std::chrono::steady_clock::now() > deadline)
                return Error{-ETIMEDOUT, "unloadusr: component '" + std::string(c.name) + "' (pid " +
                                             std::to_string(c.pid) + ") did not exit after SIGTERM"};
            std::this_thread::sleep_for(poll_interval);
        }
        // The process died without hal_exit(): remove what it left behind.
        hal_comp_remove_dead(c.id);
        if (s)
            s->info("Userspace component '" + std::string(c.name) + "' unloaded");
    }
    return ok();
}

Result<void> cmd_unloadusr(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_LOAD, "unloadusr"); !r)
        return r;
    return unload_user_components(&s, args[0]);
}

Result<void> cmd_waitusr(Session& s, Args args)
{
    hal_comp_info c;
    if (hal_find_comp(args[0].c_str(), &c) != 0)
        return Error{-ENOENT, "waitusr: no component named '" + args[0] + "'"};
    if (c.is_realtime)
        return Error{-EINVAL, "waitusr: '" + args[0] + "' is a realtime component, not a userspace one"};
    hal_comp_info now;
    while (hal_find_comp(c.name, &now) == 0 && now.id == c.id && process_alive(c.pid)) {
        waitpid(c.pid, nullptr, WNOHANG);
        std::this_thread::sleep_for(poll_interval);
    }
    s.info("Userspace component '" + args[0] + "' is gone");
    return ok();
}

Result<void> cmd_unload(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_LOAD, "unload"); !r)
        return r;
    const std::string& name = args[0];
    if (name == "all") {
        if (auto r = unload_user_components(&s, "all"); !r)
            return r;
        Result<void> r = rt_unload("all");
        if (!r)
            return Error{r.error().code, r.error().message};
        return ok();
    }
    hal_comp_info c;
    if (hal_find_comp(name.c_str(), &c) != 0)
        return Error{-ENOENT, "unload: no component named '" + name + "'"};
    if (!c.is_realtime)
        return unload_user_components(&s, name);
    Result<void> r = rt_unload(c.module[0] ? std::string(c.module) : name);
    if (!r)
        return Error{r.error().code, r.error().message};
    return ok();
}

}  // namespace hal::halcmd
