// SPDX-License-Identifier: GPL-2.0-or-later
// program_args.hpp - the command line milltask, io and halui share: "-ini FILE [-bus PATH]"
// (LinuxCNC's launcher starts both with -ini), plus -h.
#pragma once

#include <csignal>
#include <string>

namespace hal::bus {

struct ProgramArgs {
    std::string ini_path;
    std::string bus_path;   // empty: derived from the INI file (resolve_socket_path)
};

// Parses argv into 'out'. Returns -1 to go on, or the exit status to leave with now:
// 0 after -h (usage on stdout), 2 for an unknown argument or no -ini (message naming
// 'prog' and the usage on stderr).
int parse_program_args(const char* prog, int argc, char** argv, ProgramArgs& out);

// SIGTERM and SIGINT (the launcher's clean-up, Ctrl-C) set the returned flag, which the
// program's loop polls to end cleanly; SIGPIPE is ignored (a bus peer that went away is
// an error return, not a death).
volatile std::sig_atomic_t* install_stop_signals();

}  // namespace hal::bus
