// SPDX-License-Identifier: GPL-2.0-or-later
// launch.cpp - see launch.hpp.
#include "launch.hpp"

#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include "procs.hpp"
#include "twopass.hpp"

namespace hal::launcher {

void Launch::say(const std::string& msg) const
{
    if (opts_.verbose)
        std::fprintf(stderr, "%s: %s\n", tools_.prog.c_str(), msg.c_str());
}

void Launch::fail(const std::string& msg) const
{
    std::fflush(stdout);
    std::fprintf(stderr, "%s: %s\n", tools_.prog.c_str(), msg.c_str());
}

int Launch::halcmd(std::vector<std::string> args, const std::string& stdin_text)
{
    args.insert(args.begin(), tools_.halcmd);
    return run_program(args, opts_.trace, stdin_text);
}

int Launch::run()
{
    bool ok = start_up();
    int status = ok ? 0 : 1;
    if (ok && !stop_signal)
        status = run_display();
    if (stop_signal)
        say(std::string("stopping on signal ") + strsignal(stop_signal));
    clean_up();
    return status;
}

bool Launch::start_up()
{
    say("starting realtime");
    if (int st = run_program({tools_.realtime, "start"}, opts_.trace); st != 0) {
        fail("realtime start " + describe_status(st) + "; cleaning up");
        return false;
    }
    realtime_up_ = true;
    if (!plan_.io.empty() && !start_component("[EMCIO]EMCIO", "iocontrol", plan_.io, io_))
        return false;
    if (!plan_.halui.empty() && !start_component("[HAL]HALUI", "halui", plan_.halui, halui_))
        return false;
    if (!(plan_.twopass ? run_twopass() : run_halfiles()))
        return false;
    // Task in the background (2.9): its component "inihal" is ready once it has loaded
    // the INI into motion, which needs the threads running: waited for after "start".
    say("starting task: " + plan_.task[0]);
    std::vector<std::string> task{tools_.halcmd, "loadusr", "-Wn", "inihal"};
    task.insert(task.end(), plan_.task.begin(), plan_.task.end());
    auto pid = spawn(task, true, opts_.trace);
    if (!pid) {
        fail("[TASK]TASK: " + pid.error().message + "; cleaning up");
        return false;
    }
    task_ = *pid;
    if (!run_halcmds())
        return false;
    say("starting the threads");
    if (int st = halcmd({"start"}); st != 0) {
        fail("halcmd start " + describe_status(st) + "; cleaning up");
        return false;
    }
    if (!wait_task())
        return false;
    start_apps();
    return !stop_signal;
}

// "halcmd loadusr -Wn COMP PROG -ini INI": halcmd returns once the component is ready.
bool Launch::start_component(const char* what, const char* comp, const std::vector<std::string>& argv,
                             pid_t& group)
{
    say(std::string("starting ") + what + ": " + argv[0]);
    std::vector<std::string> cmd{tools_.halcmd, "loadusr", "-Wn", comp};
    cmd.insert(cmd.end(), argv.begin(), argv.end());
    auto pid = spawn(cmd, true, opts_.trace);
    if (!pid) {
        fail(std::string(what) + ": " + pid.error().message + "; cleaning up");
        return false;
    }
    group = *pid;
    int st = wait_for(*pid, true);
    if (st == -1)
        return false;
    if (st != 0) {
        fail(std::string(what) + " '" + argv[0] + "' did not start (halcmd loadusr " + describe_status(st) +
             "); cleaning up");
        return false;
    }
    return true;
}

bool Launch::run_halfiles()
{
    for (const HalFile& f : plan_.halfiles) {
        if (stop_signal)
            return false;
        say("running HAL file " + f.path);
        std::vector<std::string> args;
        if (f.is_tcl) {
            args = {"haltcl", "-i", plan_.ini, f.path};
            args.insert(args.end(), f.args.begin(), f.args.end());
        } else {
            args = {tools_.halcmd, "-i", plan_.ini};
            if (opts_.keep_going)
                args.push_back("-k");
            args.insert(args.end(), {"-f", f.path});
        }
        int st = run_program(args, opts_.trace);
        if (st != 0 && !opts_.keep_going) {
            fail("HAL file " + f.path + " (" + f.where + ") failed; cleaning up");
            return false;
        }
        if (st != 0)
            fail("HAL file " + f.path + " (" + f.where + ") failed; going on (-k)");
    }
    return true;
}

bool Launch::run_twopass()
{
    std::vector<std::pair<std::string, std::string>> files;
    for (const HalFile& f : plan_.halfiles) {
        if (f.is_tcl) {
            fail(f.where + ": TWOPASS cannot split the Tcl file " + f.path + "; cleaning up");
            return false;
        }
        std::ifstream in(f.path);
        std::stringstream ss;
        ss << in.rdbuf();
        files.emplace_back(f.path, ss.str());
    }
    auto split = twopass_split(files);
    if (!split) {
        fail(split.error().message + "; cleaning up");
        return false;
    }
    say("TWOPASS: pass 0, " + std::to_string(split->pass0.size()) + " load commands");
    for (const PassZeroCommand& c : split->pass0) {
        if (stop_signal)
            return false;
        if (halcmd({"-i", plan_.ini, "-f"}, c.line + "\n") != 0) {
            fail(c.where + ": '" + c.line + "' failed (TWOPASS pass 0)" +
                 (opts_.keep_going ? "; going on (-k)" : "; cleaning up"));
            if (!opts_.keep_going)
                return false;
        }
    }
    // Pass 1 from a copy with the load lines blanked: same name and line numbers.
    char tmpl[] = "/tmp/emc-twopass.XXXXXX";
    if (!mkdtemp(tmpl)) {
        fail("TWOPASS: cannot make a temporary directory; cleaning up");
        return false;
    }
    std::string dir = tmpl;
    bool ok = true;
    for (size_t i = 0; ok && i < split->pass1.size(); i++) {
        const TwoPassFile& f = split->pass1[i];
        std::string copy = dir + "/" + std::to_string(i) + "-" + f.path.substr(f.path.rfind('/') + 1);
        std::ofstream(copy) << f.pass1_text;
        say("TWOPASS: pass 1, " + f.path);
        std::vector<std::string> args{"-i", plan_.ini};
        if (opts_.keep_going)
            args.push_back("-k");
        args.insert(args.end(), {"-f", copy});
        int st = halcmd(args);
        unlink(copy.c_str());
        if (st != 0) {
            fail("HAL file " + f.path + " failed (TWOPASS pass 1)" +
                 (opts_.keep_going ? "; going on (-k)" : "; cleaning up"));
            ok = opts_.keep_going;
        }
    }
    rmdir(dir.c_str());
    return ok;
}

bool Launch::run_halcmds()
{
    for (size_t i = 0; i < plan_.halcmds.size(); i++) {
        if (stop_signal)
            return false;
        say("[HAL]HALCMD " + plan_.halcmds[i]);
        std::vector<std::string> args{"-i", plan_.ini};
        if (opts_.keep_going)
            args.push_back("-k");
        args.push_back("-f");
        if (halcmd(args, plan_.halcmds[i] + "\n") != 0) {
            fail(plan_.halcmd_where[i] + ": [HAL]HALCMD '" + plan_.halcmds[i] + "' failed" +
                 (opts_.keep_going ? "; going on (-k)" : "; cleaning up"));
            if (!opts_.keep_going)
                return false;
        }
    }
    return true;
}

bool Launch::wait_task()
{
    int st = wait_for(task_, true);
    if (st == -1)
        return false;
    if (st != 0) {
        fail("[TASK]TASK '" + plan_.task[0] + "' did not start (halcmd loadusr " + describe_status(st) +
             "); cleaning up");
        return false;
    }
    say("task is ready");
    return true;
}

void Launch::start_apps()
{
    for (const Program& app : plan_.apps) {
        for (int ms = 0; ms < plan_.app_delay * 1000 && !stop_signal; ms += 50)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        if (stop_signal)
            return;
        say("starting application " + app.argv[0]);
        auto pid = spawn(app.argv, true, opts_.trace);
        if (!pid)
            fail(app.where + ": [APPLICATIONS]APP: " + pid.error().message + " (going on)");
        else
            apps_.push_back(*pid);
    }
}

int Launch::run_display()
{
    switch (plan_.display) {
    case DisplayKind::none:
        say("no [DISPLAY]DISPLAY: running headless until SIGINT or SIGTERM");
        while (!stop_signal)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        return 0;
    case DisplayKind::dummy: {
        std::printf("%s: running with the dummy display; press Enter to stop\n", tools_.prog.c_str());
        std::fflush(stdout);
        char c;
        while (!stop_signal) {
            ssize_t n = read(0, &c, 1);
            if (n == 0 || (n == 1 && c == '\n') || (n < 0 && errno != EINTR))
                break;
        }
        return 0;
    }
    case DisplayKind::program:
        break;
    }
    say("starting the display: " + plan_.display_program.argv[0]);
    auto pid = spawn(plan_.display_program.argv, false, opts_.trace);
    if (!pid) {
        fail(plan_.display_program.where + ": [DISPLAY]DISPLAY: " + pid.error().message + "; cleaning up");
        return 1;
    }
    display_ = *pid;
    int st = wait_for(display_, true);
    if (st >= 0) {
        display_ = 0;                  // reaped: nothing to stop
        say("the display " + describe_status(st));
        return st;
    }
    return 0;
}

void Launch::clean_up()
{
    say("cleaning up");
    // 1. the display and the applications
    if (display_)
        stop_group(display_, false);
    for (pid_t app : apps_)
        stop_group(app, true);
    if (realtime_up_ && !plan_.shutdown.empty()) {   // 2. [HAL]SHUTDOWN
        say("running [HAL]SHUTDOWN " + plan_.shutdown);
        if (halcmd({"-i", plan_.ini, "-k", "-f", plan_.shutdown}) != 0)
            fail("[HAL]SHUTDOWN " + plan_.shutdown + " failed (going on)");
    }
    stop_group(task_, true);           // 3. task
    if (realtime_up_) {                // 4. threads, components, halui and io
        halcmd({"stop"});
        if (halcmd({"unload", "all"}) != 0)
            fail("halcmd unload all failed (going on)");
    }
    stop_group(halui_, true);
    stop_group(io_, true);
    if (realtime_up_) {                // 5. realtime
        if (int st = run_program({tools_.realtime, "stop"}, opts_.trace); st != 0)
            fail("realtime stop " + describe_status(st));
    }
}

}  // namespace hal::launcher
