// SPDX-License-Identifier: GPL-2.0-or-later
// plan.cpp - see plan.hpp. Key defaults follow ini-and-launch.md 2.7-2.10.
#include "plan.hpp"

#include <unistd.h>

#include <cstdlib>

namespace hal::launcher {

namespace {

bool readable(const std::string& p) { return ::access(p.c_str(), R_OK) == 0; }

bool ends_with(const std::string& s, const std::string& suffix)
{
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string home_expanded(const std::string& name)
{
    if (name.size() >= 2 && name[0] == '~' && name[1] == '/') {
        const char* home = std::getenv("HOME");
        return std::string(home ? home : "") + name.substr(1);
    }
    return name;
}

}  // namespace

std::vector<std::string> split_words(const std::string& s)
{
    std::vector<std::string> out;
    std::string cur;
    for (char c : s) {
        if (c == ' ' || c == '\t') {
            if (!cur.empty())
                out.push_back(std::move(cur));
            cur.clear();
        } else {
            cur += c;
        }
    }
    if (!cur.empty())
        out.push_back(std::move(cur));
    return out;
}

Result<std::string> find_halfile(const std::string& name, const std::string& ini_dir, const Search& search)
{
    if (name.starts_with("LIB:")) {
        std::string p = search.hallib + "/" + name.substr(4);
        if (!readable(p))
            return Error{-2, "'" + name + "' not found in the HAL library " + search.hallib};
        return p;
    }
    std::string n = home_expanded(name);
    if (!n.empty() && n[0] == '/') {
        if (!readable(n))
            return Error{-2, "'" + name + "' not found"};
        return n;
    }
    std::vector<std::string> dirs = search.hal_dirs;
    dirs.push_back(ini_dir);
    if (!search.hallib.empty())
        dirs.push_back(search.hallib);
    for (const std::string& d : dirs) {
        std::string p = d + "/" + n;
        if (readable(p))
            return p;
    }
    std::string tried;
    for (const std::string& d : dirs)
        tried += (tried.empty() ? "" : ", ") + d;
    return Error{-2, "'" + name + "' not found (searched " + tried + ")"};
}

std::string find_app(const std::string& name, const std::string& ini_dir)
{
    std::string n = home_expanded(name);
    if (n.empty() || n[0] == '/')
        return n;
    if (n.starts_with("./"))
        return ini_dir + "/" + n.substr(2);
    std::string beside = ini_dir + "/" + n;
    if (n.find('/') != std::string::npos || ::access(beside.c_str(), X_OK) == 0)
        return beside;
    return n;                          // execvp searches PATH
}

Result<Plan> make_plan(const hal::ini::IniFile& ini, const Search& search)
{
    Plan p;
    p.ini = ini.path();
    size_t slash = p.ini.rfind('/');
    p.ini_dir = slash == 0 ? "/" : p.ini.substr(0, slash);

    // io: [EMCIO]EMCIO, default "io"; an empty value means no separate io process.
    std::vector<std::string> io = split_words(ini.find("EMCIO", "EMCIO").value_or("io"));
    if (!io.empty()) {
        p.io = io;
        p.io.push_back("-ini");
        p.io.push_back(p.ini);
    }
    if (auto halui = ini.find("HAL", "HALUI"); halui && !split_words(*halui).empty()) {
        p.halui = split_words(*halui);
        p.halui.push_back("-ini");
        p.halui.push_back(p.ini);
    }
    auto task = ini.find("TASK", "TASK");
    if (!task || split_words(*task).empty())
        return Error{-22, ini.where("TASK", "TASK") + ": [TASK]TASK is not set: name the task program (milltask)"};
    p.task = split_words(*task);
    p.task.push_back("-ini");
    p.task.push_back(p.ini);

    auto halfiles = ini.find_all("HAL", "HALFILE");
    for (size_t i = 0; i < halfiles.size(); i++) {
        std::vector<std::string> words = split_words(halfiles[i]);
        std::string where = ini.where("HAL", "HALFILE", static_cast<int>(i) + 1);
        if (words.empty())
            return Error{-22, where + ": [HAL]HALFILE is empty"};
        auto path = find_halfile(words[0], p.ini_dir, search);
        if (!path)
            return Error{-2, where + ": [HAL]HALFILE " + path.error().message};
        HalFile f{*path, {words.begin() + 1, words.end()}, where, ends_with(words[0], ".tcl")};
        p.halfiles.push_back(std::move(f));
    }
    p.twopass = !ini.find("HAL", "TWOPASS").value_or("").empty();
    p.halcmds = ini.find_all("HAL", "HALCMD");
    for (size_t i = 0; i < p.halcmds.size(); i++)
        p.halcmd_where.push_back(ini.where("HAL", "HALCMD", static_cast<int>(i) + 1));
    if (auto sd = ini.find("HAL", "SHUTDOWN"); sd && !sd->empty()) {
        auto path = find_halfile(*sd, p.ini_dir, search);
        if (!path)
            return Error{-2, ini.where("HAL", "SHUTDOWN") + ": [HAL]SHUTDOWN " + path.error().message};
        p.shutdown = *path;
    }

    auto delay = ini.get_double("APPLICATIONS", "DELAY", 0);
    if (!delay)
        return delay.error();
    if (*delay < 0 || *delay > 3600)
        return Error{-22, ini.where("APPLICATIONS", "DELAY") + ": [APPLICATIONS]DELAY must be 0..3600 seconds"};
    p.app_delay = *delay;
    auto apps = ini.find_all("APPLICATIONS", "APP");
    for (size_t i = 0; i < apps.size(); i++) {
        std::vector<std::string> words = split_words(apps[i]);
        std::string where = ini.where("APPLICATIONS", "APP", static_cast<int>(i) + 1);
        if (words.empty())
            return Error{-22, where + ": [APPLICATIONS]APP is empty"};
        words[0] = find_app(words[0], p.ini_dir);
        p.apps.push_back({words, where});
    }

    // The display: none (headless), dummy (wait for Enter), the remote shell (its own
    // options first, "-- -ini INI" as emcrsh(1) says), or PROG -ini INI ARGS.
    std::vector<std::string> disp = split_words(ini.find("DISPLAY", "DISPLAY").value_or(""));
    std::string dwhere = ini.where("DISPLAY", "DISPLAY");
    if (disp.empty()) {
        p.display = DisplayKind::none;
    } else if (disp[0] == "dummy") {
        p.display = DisplayKind::dummy;
    } else {
        p.display = DisplayKind::program;
        std::vector<std::string> argv{disp[0]};
        if (disp[0] == "emcrsh" || disp[0] == "linuxcncrsh") {
            argv.insert(argv.end(), disp.begin() + 1, disp.end());
            argv.insert(argv.end(), {"--", "-ini", p.ini});
        } else {
            argv.insert(argv.end(), {"-ini", p.ini});
            argv.insert(argv.end(), disp.begin() + 1, disp.end());
        }
        p.display_program = {argv, dwhere};
    }
    p.coordinates = ini.find("TRAJ", "COORDINATES").value_or("");
    p.kinematics = ini.find("KINS", "KINEMATICS").value_or("");
    return p;
}

}  // namespace hal::launcher
