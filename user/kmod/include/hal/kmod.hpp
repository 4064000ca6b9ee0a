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

// Env HAL_FLAVOR=kmod|uspace decides; else kmod when rtapi.ko is loaded (/proc/rtapi),
// or when modules for the running kernel are installed and the helper is there;
// else the simulated-realtime flavor (the default on a fresh machine).
Result<FlavorChoice> detect_flavor();

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

}  // namespace hal::kmod
