// SPDX-License-Identifier: GPL-2.0-or-later
// options.hpp - the launcher's command line (emc(1), ini-and-launch.md 3.1):
//   emc [-v] [-d] [-k] [-r] [-l] [-H DIR]... [-h] [INIFILE | -]
// Pure: the unit tests drive it directly.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "hal/result.hpp"

namespace hal::launcher {

struct Options {
    bool verbose = false;            // -v: say what each step does
    bool trace = false;              // -d: also echo every command run
    bool keep_going = false;         // -k: go on after a failing HAL file / HALCMD
    bool no_redirect = false;        // -r: accepted; output is never redirected here
    bool last = false;               // -l or INIFILE "-": the last INI used
    bool help = false;               // -h
    std::vector<std::string> hal_dirs;   // -H DIR: searched first for HALFILEs
    std::string inifile;             // as given (made absolute by the caller)
};

// ARGS exclude argv[0]. Options may come in any order before the INI file.
Result<Options> parse_options(std::span<const std::string> args);
// The usage text for PROG (emc or linuxcnc).
std::string usage_text(const std::string& prog);

}  // namespace hal::launcher
