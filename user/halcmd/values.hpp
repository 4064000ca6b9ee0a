// SPDX-License-Identifier: GPL-2.0-or-later
// values.hpp - HAL values as halcmd reads and prints them (RULINGS.md "halcmd output
// formats"): type names, strict parsing of setp/sets values, display formatting,
// and the name patterns of show/list. Pure: no HAL calls.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hal/result.hpp"
#include "hal_query.h"

namespace hal::halcmd {

const char* type_name(hal_type_t type);                       // "bit", "s32", "u32", "float"
std::optional<hal_type_t> parse_type_name(std::string_view name);
const char* pin_dir_name(hal_pin_dir_t dir);                  // "IN", "OUT", "I/O"
const char* param_dir_name(hal_param_dir_t dir);              // "RO", "RW"

// 1/0, true/false, on/off, yes/no in any case (RULINGS.md "bit values").
std::optional<bool> parse_bit(std::string_view text);
// bit: parse_bit(); s32/u32: decimal or 0x hex, range-checked;
// float: a full strtod() match of a finite value (no nan, inf or overflow like 1e999;
// underflow like 1e-999 rounds to the nearest double). The error says the value and what is accepted.
Result<hal_value> parse_value(hal_type_t type, std::string_view text);

// TRUE/FALSE, decimal integers, floats via format_float().
std::string format_value(hal_type_t type, const hal_value& v);
// The shortest of %.6g .. %.17g that reads back as the same double.
std::string format_float(double v);

// show/list patterns: a name matches if it starts with a pattern or matches it as
// a shell glob (fnmatch); no patterns match everything.
bool name_matches(const std::vector<std::string>& patterns, std::string_view name);

}  // namespace hal::halcmd
