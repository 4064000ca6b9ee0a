// SPDX-License-Identifier: GPL-2.0-or-later
// parser.hpp - reads the text of a .comp file into a Component (grammar: LANGUAGE.md).
// Errors are one line, "FILE:LINE: problem", as comp(1) users expect from a compiler.
#pragma once

#include <string>

#include "hal/result.hpp"
#include "model.hpp"

namespace hal::comp {

// Parse and check the declarations of a .comp file. 'file' names it in messages.
// Warnings (unknown options, no license) go to 'warnings', one line each.
Result<Component> parse_comp(const std::string& text, const std::string& file,
                             std::string* warnings = nullptr);

}  // namespace hal::comp
