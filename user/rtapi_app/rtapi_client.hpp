// SPDX-License-Identifier: GPL-2.0-or-later
// rtapi_client.hpp - how halcmd loads and unloads realtime modules in the
// simulated-realtime flavor: requests to the rtapi_app daemon of $RTAPI_INSTANCE
// over its socket (protocol.hpp). Errors are one line, as the daemon worded them
// (several lines joined with "; "), with a negative errno as code.
#pragma once

#include <string>
#include <vector>

#include "hal/result.hpp"

namespace hal {

// Load 'module' with insmod-style "name=value" arguments (one per string, as
// halcmd's tokenizer leaves them). Starts rtapi_app if none answers: $RTAPI_APP,
// else "rtapi_app" beside the calling executable; waits up to 5 s for it.
Result<void> rtapi_load(const std::string& module, const std::vector<std::string>& args);

// Unload 'module', or every module ("all", newest first). With no daemon running
// nothing is loaded: "M: not loaded" ("all" succeeds). The daemon exits when the
// last module goes.
Result<void> rtapi_unload(const std::string& module);

// Start the daemon if none answers ("realtime start"); it then waits for loadrt.
Result<void> rtapi_start();

// Set the daemon's RTAPI message level (halcmd "debug"); success when none runs.
Result<void> rtapi_set_msg_level(int level);

// Loaded modules in load order; empty when no daemon runs (none is started).
Result<std::vector<std::string>> rtapi_list();

// Unload everything and stop the daemon; success when none runs.
Result<void> rtapi_shutdown();

// True when a daemon answers on this instance's socket.
bool rtapi_running();

}  // namespace hal
