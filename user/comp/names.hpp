// SPDX-License-Identifier: GPL-2.0-or-later
// names.hpp - how a .comp name becomes a HAL name and a C name (LANGUAGE.md "Names").
#pragma once

#include <string>

namespace hal::comp {

// HAL spelling: '_' -> '-', trailing '-'/'.' dropped ("in_" -> "in", "conv_bit_s32" -> "conv-bit-s32").
std::string to_hal(const std::string& name);

// printf format of a (possibly array) HAL name: each block of N '#' becomes "%0Nd".
std::string to_hal_format(const std::string& name);

// C spelling: a '#' block and the separators before it removed, '-' and '.' -> '_',
// runs of '_' collapsed ("out-#" -> "out", "min-val" -> "min_val", "in_" -> "in_").
std::string to_c(const std::string& name);

// Number of '#' blocks in the name.
int hash_blocks(const std::string& name);

// Quote text as a C string literal.
std::string c_quote(const std::string& text);

}  // namespace hal::comp
