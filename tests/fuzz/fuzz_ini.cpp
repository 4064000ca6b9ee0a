// SPDX-License-Identifier: GPL-2.0-or-later
// fuzz_ini - the shared INI reader (user/ini): any bytes parse (or not) without a
// crash, and a key that parsed reads back through every typed getter.
#include <cstdint>
#include <string>
#include <string_view>

#include "ini/ini_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    std::string_view text(reinterpret_cast<const char*>(data), size);
    auto ini = hal::ini::IniFile::parse(text, "fuzz.ini");
    if (!ini)
        return 0;
    (void)ini->find("EMC", "MACHINE");
    (void)ini->find("", "");
    for (const auto& e : ini->entries()) {
        (void)ini->get_double(e.section, e.key, 0);
        (void)ini->get_int(e.section, e.key, 0);
        (void)ini->get_bool(e.section, e.key, false);
        (void)ini->where(e.section, e.key, 2);
        (void)ini->find_all(e.section, e.key);
    }
    return 0;
}
