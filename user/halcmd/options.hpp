// SPDX-License-Identifier: GPL-2.0-or-later
// options.hpp - command-line options of halcmd and halrun (halcmd(1) OPTIONS).
// Pure: parsing never touches HAL, so the unit tests drive it directly.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "hal/result.hpp"

namespace hal::halcmd {

enum class Verbosity { silent, errors, verbose, debug };   // -Q, -q (default), -v, -V

struct Options {
    bool from_file = false;           // -f: commands come from a file (or stdin)
    std::string file;                 // -f argument; empty means stdin
    std::string inifile;              // -i: variables for [SECTION]VAR substitution
    bool keep_going = false;          // -k
    Verbosity verbosity = Verbosity::errors;
    bool script_mode = false;         // -s
    bool release_mutex = false;       // -R
    bool help = false;                // -h
    std::string help_topic;           // -h COMMAND
    std::vector<std::string> command; // a command given on the command line
    std::string flavor;               // --flavor=kernel|sim; empty: HAL_FLAVOR or detection
};

struct HalrunOptions {
    bool interactive = false;         // -I: interactive halcmd -kf before teardown
    bool force_exit = false;          // -U: tear down whatever realtime session is left
    Options halcmd;
};

// args exclude argv[0]. Options stop at the first word that is not one (the command).
Result<Options> parse_halcmd_options(std::span<const std::string> args);
// halrun [--flavor=F] [-I] [halcmd options] [file.hal] | halrun [--flavor=F] -U
Result<HalrunOptions> parse_halrun_options(std::span<const std::string> args);

}  // namespace hal::halcmd
