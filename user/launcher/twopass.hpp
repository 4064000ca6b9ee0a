// SPDX-License-Identifier: GPL-2.0-or-later
// twopass.hpp - [HAL]TWOPASS (ini-and-launch.md 2.8): pass 0 runs every loadrt and
// loadusr line of all HAL files (repeated "loadrt COMP count=/names=" lines merged
// into one), pass 1 runs the rest of each file. Pure: text in, commands out.
#pragma once

#include <string>
#include <vector>

#include "hal/result.hpp"

namespace hal::launcher {

struct PassZeroCommand {
    std::string line;                  // the (merged) command
    std::string where;                 // FILE:LINE of its first occurrence
};

struct TwoPassFile {
    std::string path;
    std::string pass1_text;            // the file with its load lines blanked (line numbers kept)
};

struct TwoPass {
    std::vector<PassZeroCommand> pass0;
    std::vector<TwoPassFile> pass1;
};

// FILES: (path, text) in HALFILE order.
Result<TwoPass> twopass_split(const std::vector<std::pair<std::string, std::string>>& files);

}  // namespace hal::launcher
