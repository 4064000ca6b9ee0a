// SPDX-License-Identifier: GPL-2.0-or-later
// meter_options.hpp - halmeter(1) command line:
//   halmeter [-s] [pin|sig|param NAME] [-g X Y [WIDTH]]         (the window)
//   halmeter -t [-l] [-i MS] [-n COUNT] pin|sig|param NAME      (terminal mode, ours)
#pragma once

#include <span>
#include <string>

#include "hal/result.hpp"

namespace hal::meter {

enum class Kind { none, pin, sig, param };

struct Item {
    Kind kind = Kind::none;
    std::string name;
};

struct MeterOptions {
    Item item;                    // what to show first; Kind::none = blank window
    bool small = false;           // -s: name in the title bar, no buttons
    bool has_geometry = false;    // -g X Y [WIDTH]
    int x = 0, y = 0;
    int width = 270;              // the page's default width
    bool terminal = false;        // -t: no window, write to stdout
    bool lines = false;           // -l: one line per update even on a terminal
    int interval_ms = 100;        // -i: update interval
    long count = 0;               // -n: stop after COUNT updates (0 = until killed)
    bool help = false;
};

// args[0] is the program name. Pure: no I/O.
Result<MeterOptions> parse_meter_options(std::span<char* const> args);

const char* kind_name(Kind k);    // "pin", "sig", "param"

inline constexpr const char* meter_usage =
    "usage: halmeter [-s] [pin|sig|param NAME] [-g X Y [WIDTH]]\n"
    "       halmeter -t [-l] [-i MS] [-n COUNT] pin|sig|param NAME\n"
    "  -s         small window: the name in the title bar, no Select/Exit buttons\n"
    "  -g X Y [W] place the window at X,Y (pixels from the top left), W pixels wide (270)\n"
    "  -t         terminal mode: no window; the value is updated in place on a terminal,\n"
    "             one line per update otherwise\n"
    "  -l         terminal mode with one line per update, also on a terminal\n"
    "  -i MS      update interval in milliseconds (default 100)\n"
    "  -n COUNT   terminal mode: exit after COUNT updates\n";

}  // namespace hal::meter
