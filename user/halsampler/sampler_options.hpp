// SPDX-License-Identifier: GPL-2.0-or-later
// sampler_options.hpp - halsampler(1) command line: halsampler [-c CHAN] [-n COUNT] [-t] [FILENAME].
#pragma once

#include <span>
#include <string>

#include "hal/result.hpp"

namespace hal {

struct SamplerOptions {
    int channel = 0;              // -c: sampler FIFO number
    unsigned long long count = 0; // -n: samples to print, 0 = until killed
    bool tag = false;             // -t: sample number in the first column
    bool help = false;            // -h: print usage and exit
    std::string filename;         // "" = stdout
};

// args[0] is the program name. Pure: no I/O.
Result<SamplerOptions> parse_sampler_options(std::span<char* const> args);

inline constexpr const char* sampler_usage =
    "usage: halsampler [-c CHAN] [-n COUNT] [-t] [FILENAME]\n"
    "  -c CHAN   read sampler FIFO CHAN (default 0)\n"
    "  -n COUNT  exit after COUNT samples (default: run until killed)\n"
    "  -t        print the sample number first on each line\n"
    "  FILENAME  write to FILENAME instead of stdout\n";

}  // namespace hal
