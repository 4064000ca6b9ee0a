// SPDX-License-Identifier: GPL-2.0-or-later
// teardown.hpp - ending a realtime session, shared by halrun (-U, end of a run) and
// realtime(1) ("realtime stop"). Each problem is printed once as "PROG: message".
#pragma once

namespace hal::halcmd {

// Stop threads, unload userspace components and realtime modules (attached).
bool teardown_attached(const char* prog);
// After the last user detached: stop rtapi_app and drop the segments (sim), or
// unload hal_lib and rtapi (kernel).
bool shutdown_realtime(const char* prog);
// halrun -U / realtime stop: release the HAL mutex, tear down whatever runs.
int force_exit(const char* prog);

}  // namespace hal::halcmd
