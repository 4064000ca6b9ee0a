// SPDX-License-Identifier: GPL-2.0-or-later
// motcmd_parse.hpp - motcmd's command words -> one motion command (or a client-side
// action: status, errors, wait-*, comp-file). Separate from main.cpp so unit tests
// check the parsing and its messages.
#pragma once

#include <string>
#include <vector>

#include "hal/result.hpp"
#include "motion_if.h"

namespace hal {

enum class MotcmdAction {
    Send,        // send `cmd`
    Status,      // print the status
    Errors,      // print and take the queued errors
    WaitInpos,   // wait until motion is in position (and not homing)
    WaitHomed,   // wait until all joints are homed
    WaitState,   // wait until motion_state == state
    CompFile,    // read `file` and send one SET_JOINT_COMP per line
};

struct MotcmdRequest {
    MotcmdAction action = MotcmdAction::Send;
    motion_command cmd{};
    int state = 0;          // WaitState
    std::string file;       // CompFile
    int comp_type = 0;      // CompFile: 0 actual positions, 1 trims
    double wait_s = 10.0;   // Wait*: give up after this long (exit status 1)
};

// words: the command name and its arguments (argv after the options).
Result<MotcmdRequest> motcmd_parse(const std::vector<std::string>& words);

// One line of a comp file ("nominal a b"): false at the first line that is not
// three numbers (motion.md 8: reading stops there).
bool motcmd_comp_line(const std::string& line, int type, double* nominal, double* fwd,
                      double* rev);

// The usage text (motcmd --help).
const char* motcmd_usage();

}  // namespace hal
