// SPDX-License-Identifier: GPL-2.0-or-later
// fuzz_comp - comp's .comp parser and its checks on any bytes.
#include <cstdint>
#include <string>

#include "parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    std::string text(reinterpret_cast<const char*>(data), size);
    std::string warnings;
    (void)hal::comp::parse_comp(text, "fuzz.comp", &warnings);
    return 0;
}
