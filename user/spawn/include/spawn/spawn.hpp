// SPDX-License-Identifier: GPL-2.0-or-later
// spawn.hpp - fork/exec of a program through PATH for halcmd's loadusr and the
// launcher. A close-on-exec pipe tells the parent whether exec worked, so "no such
// program" is one error line from the parent, not a message from the child.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

#include "hal/result.hpp"

namespace hal {

struct SpawnOptions {
    bool default_signals = false;   // SIGINT, SIGTERM, SIGHUP, SIGPIPE back to default in the child
    bool new_group = false;         // the child leads a process group of its own
    int stdin_fd = -1;              // becomes the child's stdin (closed in the child)
};

// The child's pid, or an error: "pipe: ...", "fork: ...", "cannot run 'PROG': reason"
// (the failed child is reaped).
Result<pid_t> spawn_process(const std::vector<std::string>& argv, const SpawnOptions& opt = {});

}  // namespace hal
