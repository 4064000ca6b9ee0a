// SPDX-License-Identifier: GPL-2.0-or-later
// check.hpp - the rules a parsed .comp must satisfy beyond its grammar (array names
// hold one '#' block, C names are unique, realtime components have a function, ...).
#pragma once

#include <string>

#include "hal/result.hpp"
#include "model.hpp"

namespace hal::comp {

// One "FILE:LINE: problem" error for the first broken rule; warnings are appended.
Result<void> check_component(const Component& c, std::string* warnings);

}  // namespace hal::comp
