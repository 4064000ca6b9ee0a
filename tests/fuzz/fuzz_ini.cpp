// SPDX-License-Identifier: GPL-2.0-or-later
// fuzz_ini - the INI reader behind halcmd -i: any bytes parse (or not) without a
// crash, and a key that parsed reads back.
#include <cstdint>
#include <string>
#include <string_view>

#include "ini_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    std::string_view text(reinterpret_cast<const char*>(data), size);
    auto ini = hal::halcmd::IniFile::parse(text, "fuzz.ini");
    (void)ini.get("EMC", "MACHINE");
    (void)ini.get("", "");
    // The first line's words as a section/key pair.
    std::string_view first = text.substr(0, text.find('\n'));
    size_t sp = first.find(' ');
    if (sp != std::string_view::npos)
        (void)ini.get(first.substr(0, sp), first.substr(sp + 1));
    return 0;
}
