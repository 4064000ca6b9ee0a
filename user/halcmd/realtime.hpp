// SPDX-License-Identifier: GPL-2.0-or-later
// realtime.hpp - where this run's realtime modules live: in rtapi_app (simulated
// flavor, rtapi_client.hpp) or in the kernel (kernel flavor, hal/kmod.hpp). The
// flavor is chosen once per process by select_flavor() and kept in the environment
// (HAL_FLAVOR=kernel|sim), which the ULAPI library and child programs read too.
#pragma once

#include <string>
#include <vector>

#include "hal/result.hpp"

namespace hal::halcmd {

// 'forced': "kernel", "sim" (--flavor=) or empty (env HAL_FLAVOR, else detection:
// hal::kmod::detect_flavor). Exports HAL_FLAVOR. Error: an unknown name.
Result<void> select_flavor(const std::string& forced);
bool kernel_flavor();

// Before attaching to HAL: the kernel flavor loads rtapi.ko and hal_lib.ko (they
// hold the HAL segment); nothing to do in the simulated flavor.
Result<void> rt_prepare();

// loadrt / unloadrt (NAME or "all": every realtime module, newest first).
Result<void> rt_load(const std::string& module, const std::vector<std::string>& args);
Result<void> rt_unload(const std::string& module);

// halcmd "debug": the message level of the realtime side (rtapi_app's, or rtapi.ko's
// msg_level parameter). Nothing to do when nothing realtime runs.
Result<void> rt_set_msg_level(int level);

// Start the realtime environment without loading a component ("realtime start"):
// rtapi_app (sim), rtapi.ko + hal_lib.ko (kernel).
Result<void> rt_start();

// True when realtime modules are loaded (kernel) / rtapi_app answers (sim).
bool rt_running();

// Simulated flavor, after attaching: an error when the HAL holds realtime components
// or threads but their host, rtapi_app, is gone (killed): they no longer run, and
// nothing but "halrun -U" can clear them (issue 19, item 2). The message says so.
Result<void> rt_check_host();

// After the last detach: unload everything, including hal_lib and rtapi (kernel),
// or stop rtapi_app (sim).
Result<void> rt_shutdown();

}  // namespace hal::halcmd
