// SPDX-License-Identifier: GPL-2.0-or-later
// kmod.hpp - the userspace side of the kernel flavor: which flavor this machine runs,
// and loading/unloading realtime modules through the setuid emc_module_helper.
#pragma once

#include <string>
#include <vector>

#include "hal/result.hpp"

namespace hal::kmod {

enum class Flavor { uspace, kmod };

// Where the answer came from, for "halrun -v"-style diagnostics.
struct FlavorChoice {
    Flavor flavor = Flavor::uspace;
    std::string reason;
};

// Env HAL_FLAVOR=kernel|sim decides (kmod|uspace are accepted too); else kmod when
// rtapi.ko is loaded (/proc/rtapi),
// or when modules for the running kernel are installed and the helper is there;
// else the simulated-realtime flavor (the default on a fresh machine).
Result<FlavorChoice> detect_flavor();

// The HAL_FLAVOR value naming 'f': "kernel" or "sim". Tools export it once decided,
// so the ULAPI library (rtapi_shmem_ulapi_kmod.h) and their children agree.
const char* flavor_name(Flavor f);

// Where the modules for the running kernel are: env HAL_KMOD_DIR, else
// HAL_KMOD_INSTALL_DIR/<kernel release> (the directory emc_module_helper uses).
std::string module_dir();

// Env EMC_MODULE_HELPER, else <dir of this executable>/emc_module_helper, else the
// installed path compiled in (HAL_INSTALL_BINDIR).
std::string helper_path();

// True when /proc/modules lists 'name'.
bool module_loaded(const std::string& name);

// Names of all loaded kernel modules, in /proc/modules order.
std::vector<std::string> loaded_modules();

// emc_module_helper insert NAME ARGS... (loads rtapi and hal_lib first when missing);
// the error carries the helper's/insmod's first message line.
Result<void> load(const std::string& name, const std::vector<std::string>& args = {});

// emc_module_helper remove NAME.
Result<void> unload(const std::string& name);

// Runs the helper with 'argv' (without argv[0]); returns its exit status and stderr.
struct HelperRun {
    int status = -1;         // exit status, or -1 when it could not run / was killed
    std::string err;         // its standard error
};
HelperRun run_helper(const std::vector<std::string>& argv);

// The helper's argv that inserts rtapi or hal_lib; hal_lib gets hal_size=$HAL_SIZE
// when the environment sets HAL_SIZE (the HAL segment's size, chosen at its creation).
std::vector<std::string> core_insert_argv(const std::string& core);

// --- halcmd's loadrt/unloadrt in the kernel flavor (kmod_modules.cpp). Errors are
// worded as the simulated flavor's rtapi_app words them, so .hal files and their
// tests see the same messages in both flavors. ---

// Loaded HAL realtime modules (those using rtapi or hal_lib, not these two), newest
// first, as /proc/modules lists them.
std::vector<std::string> hal_modules();

// rtapi and hal_lib, when missing (halcmd, before it attaches to HAL).
Result<void> load_core();

// loadrt: checks the name, the arguments (syntax, and against the parameters the
// .ko declares) and that it is not loaded, then inserts it. When its
// rtapi_app_main fails, the error carries the module's error messages from
// /proc/rtapi/messages and "NAME: rtapi_app_main failed: <strerror> (<rc>)".
Result<void> load_module(const std::string& name, const std::vector<std::string>& items);

// unloadrt NAME; "all": every HAL module, dependents first. rtapi and hal_lib are
// left alone (see shutdown()).
Result<void> unload_module(const std::string& name);

// Unload and load hal_lib again, the HAL segment staying (halcmd maps it): threads
// belong to hal_lib, not to the module that made them (threads(9)), so this is how
// "unload all" ends them in the kernel flavor.
Result<void> reload_hal_lib();

// Everything: the HAL modules, then hal_lib, then rtapi.
Result<void> shutdown();

// The parameter names a .ko declares (its modinfo "parmtype=" entries).
Result<std::vector<std::string>> declared_params(const std::string& ko_path);

// /proc/rtapi/messages: the number the next message will get (0 without rtapi.ko),
// and the error messages numbered 'first' and later.
unsigned long long next_message_seq();
std::vector<std::string> error_messages_since(unsigned long long first);

}  // namespace hal::kmod
