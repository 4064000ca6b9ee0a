// SPDX-License-Identifier: GPL-2.0-or-later
// main.cpp - emc / linuxcnc (emc(1), docs/launcher.md): options, the INI file, the
// lock file, the environment, then one Launch. Exit status: the display's, 0 after a
// headless run ended by SIGINT/SIGTERM, 1 when start-up failed, 2 for bad usage.
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "ini/ini_file.hpp"
#include "launch.hpp"
#include "lockfile.hpp"
#include "options.hpp"
#include "plan.hpp"
#include "procs.hpp"

#ifndef HAL_SOURCE_HALLIB
#define HAL_SOURCE_HALLIB ""
#endif

namespace {

using namespace hal::launcher;

std::string prog_name = "emc";

int complain(const std::string& msg, int status = 1)
{
    std::fprintf(stderr, "%s: %s\n", prog_name.c_str(), msg.c_str());
    return status;
}

bool is_dir(const std::string& p)
{
    struct stat st;
    return stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

std::string exe_dir()
{
    char buf[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n <= 0)
        return "";
    std::string p(buf, static_cast<size_t>(n));
    return p.substr(0, p.rfind('/'));
}

std::string parent(const std::string& dir)
{
    size_t s = dir.rfind('/');
    return s == 0 || s == std::string::npos ? "/" : dir.substr(0, s);
}

// The tool beside the launcher (build/bin, PREFIX/bin), else PATH's.
std::string tool(const std::string& bindir, const std::string& name)
{
    std::string p = bindir + "/" + name;
    return access(p.c_str(), X_OK) == 0 ? p : name;
}

// The system HAL library for LIB: names: HALLIB_DIR, PREFIX/share/hal/hallib, or the
// source tree's lib/hallib for a launcher run from the build tree.
std::string hallib_dir(const std::string& bindir)
{
    if (const char* env = std::getenv("HALLIB_DIR"); env && *env)
        return env;
    std::string prefix = parent(bindir);
    std::string installed = (prefix == "/" ? "" : prefix) + "/share/hal/hallib";
    return is_dir(installed) ? installed : HAL_SOURCE_HALLIB;
}

std::string rc_file()
{
    if (const char* env = std::getenv("EMC_RC_FILE"); env && *env)
        return env;
    const char* home = std::getenv("HOME");
    return home ? std::string(home) + "/.emcrc" : "";
}

std::string last_config()
{
    std::string rc = rc_file();
    if (rc.empty())
        return "";
    auto ini = hal::ini::IniFile::load(rc);
    return ini ? ini->find("PICKCONFIG", "LAST_CONFIG").value_or("") : "";
}

void remember_config(const std::string& ini)
{
    std::string rc = rc_file();
    if (!rc.empty())
        std::ofstream(rc) << "[PICKCONFIG]\nLAST_CONFIG = " << ini << "\n";
}

std::string absolute(const std::string& p)
{
    char buf[PATH_MAX];
    if (realpath(p.c_str(), buf))
        return buf;
    if (!p.empty() && p[0] == '/')
        return p;
    char cwd[PATH_MAX];
    return std::string(getcwd(cwd, sizeof cwd) ? cwd : ".") + "/" + p;
}

// Another launcher holds the lock: without a terminal the answer is yes (as 2.9's
// script), on one the user is asked. Yes = SIGTERM to it, then wait for its clean-up.
bool take_over(const std::string& lock, pid_t other)
{
    std::string q = "another " + prog_name + " (pid " + std::to_string(other) + ") is still running";
    if (isatty(0)) {
        std::fprintf(stderr, "%s: %s. Stop it and start this one? [y/N] ", prog_name.c_str(), q.c_str());
        char answer[16] = "";
        if (!std::fgets(answer, sizeof answer, stdin) || (answer[0] != 'y' && answer[0] != 'Y'))
            return false;
    } else {
        complain(q + "; stopping it (no terminal to ask)");
    }
    kill(other, SIGTERM);
    for (int i = 0; i < 300 && access(lock.c_str(), F_OK) == 0; i++)   // its clean-up: <= 30 s
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    return access(lock.c_str(), F_OK) != 0;
}

}  // namespace

int main(int argc, char** argv)
{
    std::string a0 = argv[0];
    prog_name = a0.substr(a0.rfind('/') + 1) == "linuxcnc" ? "linuxcnc" : "emc";
    std::vector<std::string> args(argv + 1, argv + argc);
    auto opts = parse_options(args);
    if (!opts)
        return complain(opts.error().message + "\n" + usage_text(prog_name), 2);
    if (opts->help) {
        std::fputs(usage_text(prog_name).c_str(), stdout);
        return 0;
    }
    std::string inifile = opts->inifile;
    if (opts->last) {
        inifile = last_config();
        if (inifile.empty())
            return complain("no last INI file recorded in " + rc_file(), 2);
    }
    if (inifile.empty())
        return complain("no INI file given (there is no graphical configuration picker)\n" + usage_text(prog_name),
                        2);
    inifile = absolute(inifile);
    auto ini = hal::ini::IniFile::load(inifile);
    if (!ini)
        return complain(ini.error().message);
    for (const std::string& w : ini->warnings())
        complain("warning: " + w, 0);

    std::string bindir = exe_dir();
    Search search{opts->hal_dirs, hallib_dir(bindir)};
    for (std::string& d : search.hal_dirs)
        d = absolute(d);
    auto plan = make_plan(*ini, search);
    if (!plan)
        return complain(plan.error().message);

    std::string lock = lock_path(prog_name);
    if (auto r = lock_create(lock); !r) {
        pid_t other = lock_owner(lock);
        if (other > 0 && other != getpid() && is_launcher(other)) {
            if (!take_over(lock, other))
                return complain(std::string("not started: ") + lock + " is held by pid " + std::to_string(other));
        } else {
            complain("removing the stale lock file " + lock, 0);
            lock_remove(lock);
        }
        if (auto again = lock_create(lock); !again)
            return complain(again.error().message);
    }
    remember_config(inifile);

    // What every program started from here finds (ini-and-launch.md 3.2).
    setenv("INI_FILE_NAME", plan->ini.c_str(), 1);
    setenv("INI_DIR_NAME", plan->ini_dir.c_str(), 1);
    setenv("EMC2_HOME", parent(bindir).c_str(), 1);
    setenv("LINUXCNC_HOME", parent(bindir).c_str(), 1);
    setenv("HALLIB_DIR", search.hallib.c_str(), 1);
    setenv("TRAJ_COORDINATES", plan->coordinates.c_str(), 1);
    setenv("KINS_KINEMATICS", plan->kinematics.c_str(), 1);
    if (!bindir.empty()) {
        const char* path = std::getenv("PATH");
        setenv("PATH", (bindir + ":" + (path ? path : "/usr/bin:/bin")).c_str(), 1);
    }
    install_signal_handlers();
    // Relative names in HAL files, the parameter file and "." in the HAL search path
    // are INI-relative.
    if (chdir(plan->ini_dir.c_str()) != 0) {
        lock_remove(lock);
        return complain("cannot change to " + plan->ini_dir + ": " + std::strerror(errno));
    }
    Tools tools{tool(bindir, "halcmd"), tool(bindir, "realtime"), prog_name};
    int status = Launch(std::move(*opts), std::move(*plan), std::move(tools)).run();
    lock_remove(lock);
    return status;
}
