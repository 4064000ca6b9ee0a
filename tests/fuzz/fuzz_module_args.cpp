// SPDX-License-Identifier: GPL-2.0-or-later
// fuzz_module_args - loadrt arguments in the joined form the rtapi_app socket
// carries. Invariant: what parses joins to text that parses back to the same list.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "module_args.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    std::string_view text(reinterpret_cast<const char*>(data), size);
    (void)hal::is_module_name(text.substr(0, text.find(' ')));
    auto args = hal::parse_module_args("fuzz", text);
    if (!args)
        return 0;
    (void)hal::check_module_args("fuzz", *args, {"count", "names", "cfg", "depth"});
    auto joined = hal::join_module_args("fuzz", *args);
    if (!joined)
        return 0;  // a value no quoting can carry: refused, fine
    auto again = hal::parse_module_args("fuzz", *joined);
    if (!again || *again != *args)
        std::abort();
    return 0;
}
