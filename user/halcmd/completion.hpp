// SPDX-License-Identifier: GPL-2.0-or-later
// completion.hpp - tab-completion candidates for interactive halcmd. Pure: given the
// line up to the cursor and a HAL snapshot, returns the names that fit the argument
// position (setp: writable params and unlinked input pins; net: the signal, then
// pins of its type; addf: functs, then threads; loadrt: module names ...).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "snapshot.hpp"

namespace hal::halcmd {

struct CompletionSources {
    const Snapshot* hal = nullptr;
    std::vector<std::string> commands;   // command names of the dispatch table
    std::vector<std::string> modules;    // loadable realtime modules
};

struct Completion {
    std::vector<std::string> candidates; // sorted, unique, all starting with the word
    bool filenames = false;              // let the line editor complete file names
};

Completion complete(std::string_view before_cursor, const CompletionSources& src);

}  // namespace hal::halcmd
