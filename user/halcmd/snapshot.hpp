// SPDX-License-Identifier: GPL-2.0-or-later
// snapshot.hpp - a copy of every HAL object, sorted for display: pins, params,
// signals, functs and threads by name, components by id. show, list, save and tab
// completion work on a snapshot; single commands use hal_find_* instead (O(1)).
#pragma once

#include <string>
#include <vector>

#include "hal_query.h"

namespace hal::halcmd {

struct ThreadEntry {
    hal_thread_info info;
    std::vector<std::string> functs;     // in execution order
};

struct Snapshot {
    std::vector<hal_comp_info> comps;    // ascending id (= load order)
    std::vector<hal_pin_info> pins;
    std::vector<hal_param_info> params;
    std::vector<hal_sig_info> sigs;
    std::vector<hal_funct_info> functs;
    std::vector<ThreadEntry> threads;
    std::vector<hal_alias_info> aliases;  // by alias name
};

// Reads the attached HAL. Takes and drops the HAL mutex once per object kind.
Snapshot take_snapshot();

}  // namespace hal::halcmd
