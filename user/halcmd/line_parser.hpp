// SPDX-License-Identifier: GPL-2.0-or-later
// line_parser.hpp - turns one halcmd line into words (halcmd(1) COMMANDS and
// SUBSTITUTION): "double" and 'single' quotes, '#' comments outside quotes,
// $VAR / $(VAR) environment and [SECTION]VAR / [SECTION](VAR) inifile substitution,
// and trailing-backslash continuation lines. Pure: the environment is a callback.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hal/result.hpp"
#include "ini/ini_file.hpp"

namespace hal::halcmd {

using hal::ini::IniFile;   // user/ini: the reader every tool shares

struct Substitutions {
    // Environment lookup; nullopt = not set. Empty function = no variable is set.
    std::function<std::optional<std::string>(const std::string&)> env;
    const IniFile* ini = nullptr;    // null: [SECTION]VAR is left as written
};

// Substitutions from the process environment and an optional inifile.
Substitutions process_substitutions(const IniFile* ini);

// Split a logical line into words. Unquoted substituted values are split at
// whitespace (as if written in the line); inside "double quotes" they are not;
// 'single quotes' take everything literally. An unknown variable is an error naming it.
Result<std::vector<std::string>> tokenize(std::string_view line, const Substitutions& subs);

// Append a physical line (without its '\n') to a logical line. Returns true when
// the physical line ended in a backslash, i.e. the logical line continues. The
// backslash goes and the next line is appended directly (no blank is inserted).
bool join_continuation(std::string& logical, std::string_view physical);

// "=>", "<=" or "<=>": direction arrows net/linkps/linksp/linkpp accept and ignore.
bool is_arrow(std::string_view word);

}  // namespace hal::halcmd
