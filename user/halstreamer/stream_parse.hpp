// SPDX-License-Identifier: GPL-2.0-or-later
// stream_parse.hpp - halstreamer(1) input: options, and one line of
// whitespace-separated values checked against the streamer's cfg string
// (floats as strtod(3) reads them, s32/u32 as strtol/strtoul in decimal, bits 0/1).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hal/result.hpp"
#include "streamer_fifo.h"

namespace hal {

struct StreamerOptions {
    int channel = 0;       // -c: streamer FIFO number
    bool help = false;     // -h
    std::string filename;  // "" = stdin
};

// args[0] is the program name. Pure: no I/O.
Result<StreamerOptions> parse_streamer_options(std::span<char* const> args);

inline constexpr const char* streamer_usage =
    "usage: halstreamer [-c CHAN] [FILENAME]\n"
    "  -c CHAN   write to streamer FIFO CHAN (default 0)\n"
    "  FILENAME  read from FILENAME instead of stdin\n";

// True for a line with nothing but whitespace (skipped silently).
bool is_blank_line(std::string_view line);

// The values of one line, one per cfg character; the error message says which
// value is wrong and why (the caller prefixes "line N: ").
Result<std::vector<hal_fifo_value>> parse_stream_line(std::string_view cfg, std::string_view line);

}  // namespace hal
