// SPDX-License-Identifier: GPL-2.0-or-later
// module_args.hpp - insmod-style "name=value" module arguments (halcmd(1) loadrt):
// syntax checks, quote removal, last-wins duplicates, the check against the
// parameters a module declares, and the one-line form used by the rtapi_app socket
// and shown by "show comp". Pure C++: no RTAPI, so halcmd and the tests can use it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "hal/result.hpp"

namespace hal {

struct ModuleArg {
    std::string name;   // parameter name, never empty
    std::string value;  // quotes removed; may be empty ("name=")
    bool operator==(const ModuleArg&) const = default;
};

// A module name: 1 to 31 (RTAPI_NAME_LEN) characters of a-z, 0-9 and _. It becomes
// a file name, so nothing else is accepted.
bool is_module_name(std::string_view name);

// Parse arguments given one per string, as halcmd's tokenizer hands them over
// (already unquoted by it; a value still wrapped in one pair of quotes, as insmod
// would see it, loses them). 'module' only names the module in error messages.
// Errors: "M: parameter 'x' has no value (use x=VALUE)", "M: argument '=1' has no
// parameter name". A name given twice keeps its first position and its last value.
Result<std::vector<ModuleArg>> parse_module_args(std::string_view module,
                                                 const std::vector<std::string>& items);

// Parse one joined string (the socket form): items split at blanks outside quotes,
// a quoted run ("a b" or 'a b') may sit anywhere in an item and its quotes are
// removed; the first '=' (even a quoted one, as in the kernel's parser) ends the
// name. Unterminated quote -> error.
Result<std::vector<ModuleArg>> parse_module_args(std::string_view module,
                                                 std::string_view joined);

// Refuse any argument whose name is not in 'declared':
// "M: unknown parameter 'foo'" (Linux only warns; we refuse, see the brief).
Result<void> check_module_args(std::string_view module, const std::vector<ModuleArg>& args,
                               const std::vector<std::string>& declared);

// The joined form that parse_module_args(module, joined) reads back unchanged:
// values holding blanks or quotes are quoted. Fails for a value holding a newline,
// a NUL, or both kinds of quote (no quoting could carry it).
Result<std::string> join_module_args(std::string_view module, const std::vector<ModuleArg>& args);

}  // namespace hal
