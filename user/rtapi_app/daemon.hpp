// SPDX-License-Identifier: GPL-2.0-or-later
// daemon.hpp - rtapi_app's socket server (protocol.hpp): connections are read
// concurrently, requests answered one at a time (loads are serialized). Runs until
// "shutdown", SIGTERM/SIGINT, or an unload that leaves no module loaded; then
// unloads everything and removes its socket.
#pragma once

namespace hal {

// Serve on the socket of $RTAPI_INSTANCE. Returns the process exit status: 0 after
// a normal end (or when another rtapi_app already serves the instance), 1 when the
// socket cannot be set up (reason on stderr).
int run_daemon();

}  // namespace hal
