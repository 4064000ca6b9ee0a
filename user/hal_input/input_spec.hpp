// SPDX-License-Identifier: GPL-2.0-or-later
// input_spec.hpp - hal_input(1)'s command line and device matching, pure:
//   hal_input [-KRAL] inputspec ...
// An inputspec is N (/dev/input/eventN) or a string matched, as a substring or a shell
// pattern, against a device's name, phys and id ("Bus=0003 Vendor=046d Product=c00e
// Version=0111"), with ":N" picking the N-th match and a leading "+" asking for
// exclusive access. A -KRAL option selects the features of the spec that follows.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hal/result.hpp"

namespace hal::input {

struct Features {
    bool keys = true, rel = true, abs = true, leds = true;   // no -XXXX option: all
};

struct InputSpec {
    std::string text;              // as given, for messages
    Features features;
    bool exclusive = false;        // leading '+'
    int event_number = -1;         // "N": /dev/input/eventN
    std::string pattern;           // otherwise
    int index = 0;                 // ":N"
};

struct DeviceInfo {
    int event_number = -1;         // N of /dev/input/eventN
    std::string devnode;
    std::string name, phys, id;    // as /proc/bus/input/devices shows them
};

Result<std::vector<InputSpec>> parse_input_args(std::span<char* const> args);

// "Bus=0003 Vendor=046d Product=c00e Version=0111" from the numbers.
std::string format_id(unsigned bus, unsigned vendor, unsigned product, unsigned version);

bool device_matches(const InputSpec& spec, const DeviceInfo& d);

// The device 'spec' selects among 'devices' (sorted by event number here): the
// index-th match. nullopt if there is none.
std::optional<DeviceInfo> select_device(const InputSpec& spec, std::vector<DeviceInfo> devices);

inline constexpr const char* input_usage =
    "usage: hal_input [-KRAL] inputspec ...\n"
    "  inputspec: N (/dev/input/eventN), or a substring or shell pattern of the device's\n"
    "             name, phys or id, with :N for the N-th match; a leading + grabs the device\n"
    "  -KRAL      export only keys (K), relative axes (R), absolute axes (A), LEDs (L)\n"
    "             of the inputspec that follows\n";

}  // namespace hal::input
