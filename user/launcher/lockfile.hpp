// SPDX-License-Identifier: GPL-2.0-or-later
// lockfile.hpp - one machine per lock file (ini-and-launch.md 3.2 step 4): the file
// holds the launcher's pid. A second launch finds it and either removes a stale one
// (its pid is gone or is not a launcher) or stops the running instance (after
// asking, on a terminal) and waits for its clean-up to remove the file.
#pragma once

#include <sys/types.h>

#include <string>

#include "hal/result.hpp"

namespace hal::launcher {

// /tmp/emc.lock (or /tmp/linuxcnc.lock when run as linuxcnc); EMC_LOCK_FILE overrides.
// A simulated-flavor instance other than 0 (RTAPI_INSTANCE) has a lock of its own.
std::string lock_path(const std::string& prog);

// The pid recorded in PATH, or 0 when there is none (no file, no number).
pid_t lock_owner(const std::string& path);

// Whether PID runs the same program as we do (/proc/PID/exe), i.e. is a launcher.
bool is_launcher(pid_t pid);

// Creates PATH holding our pid; fails if it exists.
Result<void> lock_create(const std::string& path);
void lock_remove(const std::string& path);

}  // namespace hal::launcher
