// SPDX-License-Identifier: GPL-2.0-or-later
// module_dir.hpp - where realtime modules live (for loadrt completion): env
// HAL_RTLIB_DIR, else <dir of this executable>/../rtlib, else HAL_INSTALL_RTLIB.
#pragma once

#include <string>
#include <vector>

namespace hal::halcmd {

std::string rtlib_dir();
// Module names (file names without .so/.ko), sorted; empty if the directory is unreadable.
std::vector<std::string> list_modules(const std::string& dir);

}  // namespace hal::halcmd
