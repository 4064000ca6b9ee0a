// SPDX-License-Identifier: GPL-2.0-or-later
// fuzz_values - setp/sets value parsing for every type. Invariant: a value that
// parses prints as text that parses back to the same value (what save relies on).
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "values.hpp"

using namespace hal::halcmd;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    std::string_view text(reinterpret_cast<const char*>(data), size);
    for (hal_type_t t : {HAL_BIT, HAL_S32, HAL_U32, HAL_S64, HAL_U64, HAL_FLOAT}) {
        auto v = parse_value(t, text);
        if (!v)
            continue;
        std::string shown = format_value(t, *v);
        auto back = parse_value(t, shown);
        if (!back)
            std::abort();  // printed a value setp would refuse
        bool same = t == HAL_BIT   ? back->b == v->b
                    : t == HAL_S32 ? back->s == v->s
                    : t == HAL_U32 ? back->u == v->u
                    : t == HAL_S64 ? back->ls == v->ls
                    : t == HAL_U64 ? back->lu == v->lu
                                   : std::memcmp(&back->f, &v->f, sizeof(double)) == 0 ||
                                         (back->f == 0 && v->f == 0);
        if (!same)
            std::abort();  // save would not rebuild the same HAL
    }
    if (auto t = parse_type_name(text); t && parse_type_name(type_name(*t)) != t)
        std::abort();  // a type name that does not read back
    std::vector<std::string> pats{std::string(text)};
    (void)name_matches(pats, "and2.0.in0");
    return 0;
}
