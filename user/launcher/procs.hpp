// SPDX-License-Identifier: GPL-2.0-or-later
// procs.hpp - starting and stopping the launcher's children. Background programs
// (io, halui, task, applications) each lead a process group of their own, so
// everything they start (halcmd loadusr's child) is stopped with them.
#pragma once

#include <sys/types.h>

#include <csignal>
#include <string>
#include <vector>

#include "hal/result.hpp"

namespace hal::launcher {

// Set by the SIGINT/SIGTERM/SIGHUP handler: every wait below gives up when it is set.
extern volatile std::sig_atomic_t stop_signal;
void install_signal_handlers();

// Starts ARGV (PATH search). NEW_GROUP: the child leads its own process group.
// STDIN_TEXT non-empty: written to the child's stdin (HALCMD lines).
Result<pid_t> spawn(const std::vector<std::string>& argv, bool new_group, bool trace);

// Waits for PID; returns its exit status (128+signal when killed). When
// INTERRUPTIBLE and a stop signal arrives first, returns -1 and leaves it running.
int wait_for(pid_t pid, bool interruptible);

// Runs ARGV in the foreground and returns its exit status (127: could not start).
int run_program(const std::vector<std::string>& argv, bool trace, const std::string& stdin_text = "");

// SIGTERM to the group (or process) PID, polling every 0.1 s for 2 s, then SIGKILL
// (ini-and-launch.md 3.4). Reaps PID if it is our child.
void stop_group(pid_t pid, bool is_group);

// Whether PID exists (a zombie counts as gone).
bool alive(pid_t pid);

std::string describe_status(int status);

}  // namespace hal::launcher
