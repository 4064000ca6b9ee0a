// SPDX-License-Identifier: GPL-2.0-or-later
// gs2_options.hpp - gs2_vfd(1) command line. Each option has a short form and a long
// form written with one or two dashes (-r 9600, -rate 9600, --rate 9600).
#pragma once

#include <span>
#include <string>

#include "hal/result.hpp"

namespace hal::gs2 {

struct Gs2Options {
    int bits = 8;                       // -b: 5..8
    std::string device = "/dev/ttyS0";  // -d
    bool debug = false;                 // -g (also sets verbose)
    std::string name = "gs2_vfd";       // -n: HAL component name and pin prefix
    char parity = 'O';                  // -p even|odd|none -> 'E' 'O' 'N'
    int rate = 38400;                   // -r: one of the standard rates
    int stopbits = 1;                   // -s: 1 or 2
    int target = 1;                     // -t: Modbus slave number (1..247)
    bool verbose = false;               // -v
    bool help = false;
};

// args[0] is the program name. Pure.
Result<Gs2Options> parse_gs2_options(std::span<char* const> args);

inline constexpr const char* gs2_usage =
    "usage: gs2_vfd [OPTIONS]\n"
    "  -b, -bits N         data bits, 5..8 (default 8)\n"
    "  -d, -device PATH    serial device (default /dev/ttyS0)\n"
    "  -g, -debug          print every Modbus message in hex (sets -v)\n"
    "  -n, -name NAME      HAL component name and pin prefix (default gs2_vfd)\n"
    "  -p, -parity P       even, odd or none (default odd)\n"
    "  -r, -rate N         110 300 600 1200 2400 4800 9600 19200 38400 57600 115200 (default 38400)\n"
    "  -s, -stopbits N     1 or 2 (default 1)\n"
    "  -t, -target N       Modbus target (slave) number, as set on the drive (default 1)\n"
    "  -v, -verbose        report serial errors as they happen\n";

}  // namespace hal::gs2
