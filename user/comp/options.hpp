// SPDX-License-Identifier: GPL-2.0-or-later
// options.hpp - the comp(1) command line:
//   comp [--compile|--preprocess|--document|--view-doc|--install|--install-doc]
//        [--userspace] [-o OUT] FILE...
#pragma once

#include <span>
#include <string>
#include <vector>

#include "hal/result.hpp"

namespace hal::comp {

enum class Mode { Compile, Preprocess, Document, ViewDoc, Install, InstallDoc };

struct Options {
    Mode mode = Mode::Preprocess;
    bool mode_given = false;
    bool userspace = false;
    bool help = false;
    std::string output;              // -o: only with one input file
    std::string extra_compile_args;  // --extra-compile-args=ARGS: added to the compiler's
    std::string extra_link_args;     // --extra-link-args=ARGS: added when linking
    int personalities = 64;          // --personalities=N: size of the personality= array
    std::vector<std::string> files;
};

// argv[0] is skipped. Errors say which argument is wrong.
Result<Options> parse_options(std::span<char*> argv);

std::string usage(const std::string& prog);

}  // namespace hal::comp
