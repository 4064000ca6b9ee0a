// SPDX-License-Identifier: GPL-2.0-or-later
// plan.hpp - what a launch will do, read from the INI file before anything starts
// (ini-and-launch.md 3.2 step 3): programs, HAL files with their lookup resolved,
// HALCMD lines, applications and the display. Pure apart from file-existence checks,
// so the unit tests drive it with temporary files.
#pragma once

#include <string>
#include <vector>

#include "hal/result.hpp"
#include "ini/ini_file.hpp"

namespace hal::launcher {

struct HalFile {
    std::string path;                  // resolved, absolute or INI-dir relative
    std::vector<std::string> args;     // words after the name (for .tcl files)
    std::string where;                 // "ini:line" of its HALFILE entry
    bool is_tcl = false;
};

struct Program {
    std::vector<std::string> argv;     // program and arguments, as it is started
    std::string where;                 // "ini:line" of the key naming it
};

enum class DisplayKind { none, dummy, program };

struct Plan {
    std::string ini;                   // absolute INI path
    std::string ini_dir;
    std::vector<std::string> io;       // "halcmd loadusr -Wn iocontrol ..." argv; empty: none
    std::vector<std::string> halui;    // idem for halui
    std::vector<std::string> task;     // the task program and its arguments
    std::vector<HalFile> halfiles;
    bool twopass = false;
    std::vector<std::string> halcmds;  // [HAL]HALCMD lines
    std::vector<std::string> halcmd_where;
    std::string shutdown;              // [HAL]SHUTDOWN file, resolved; empty: none
    double app_delay = 0;
    std::vector<Program> apps;
    DisplayKind display = DisplayKind::none;
    Program display_program;
    std::string coordinates;           // exported as TRAJ_COORDINATES
    std::string kinematics;            // exported as KINS_KINEMATICS
};

struct Search {
    std::vector<std::string> hal_dirs; // -H DIRs, in order
    std::string hallib;                // the system HAL library directory (LIB:)
};

// Reads INI (already loaded from an absolute path).
Result<Plan> make_plan(const hal::ini::IniFile& ini, const Search& search);

// HALFILE lookup (2.9): "LIB:name" in the library only; "/abs" as given; else the first
// readable of each -H dir, the INI dir, the library dir.
Result<std::string> find_halfile(const std::string& name, const std::string& ini_dir, const Search& search);

// [APPLICATIONS]APP lookup: absolute or ~, ./relative (INI dir), the INI dir, PATH
// (left to execvp: the name is returned as given).
std::string find_app(const std::string& name, const std::string& ini_dir);

// Split at blanks and tabs (the shell's word splitting of an unquoted INI value).
std::vector<std::string> split_words(const std::string& s);

}  // namespace hal::launcher
