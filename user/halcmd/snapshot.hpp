// SPDX-License-Identifier: GPL-2.0-or-later
// snapshot.hpp - a copy of every HAL object, sorted for display: pins, params,
// signals, functs and threads by name, components by id. show, list, save and tab
// completion work on a snapshot; single commands use hal_find_* instead (O(1)).
#pragma once

#include <functional>
#include <string>
#include <string_view>
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

// Object kinds a snapshot copies; the others stay empty. "show pin x" needs only the
// pins, and copying (and sorting) tens of thousands of other records was most of a
// short halcmd run in a big session (issue 20).
enum SnapshotKinds : unsigned {
    snap_comps = 1u << 0,
    snap_pins = 1u << 1,
    snap_params = 1u << 2,
    snap_sigs = 1u << 3,
    snap_functs = 1u << 4,
    snap_threads = 1u << 5,
    snap_aliases = 1u << 6,
    snap_all = 0x7fu,
};

// Reads the attached HAL. Takes and drops the HAL mutex once per object kind.
// With 'keep', objects of the kinds in 'filtered' whose name it rejects are left out.
Snapshot take_snapshot(unsigned kinds = snap_all, unsigned filtered = 0,
                       const std::function<bool(std::string_view)>& keep = {});

}  // namespace hal::halcmd
