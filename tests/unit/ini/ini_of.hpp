// SPDX-License-Identifier: GPL-2.0-or-later
// ini_of.hpp - the INI unit tests' parse of a text that must be valid (as "m.ini").
#pragma once

#include <gtest/gtest.h>

#include <string_view>

#include "ini/ini_file.hpp"

inline hal::ini::IniFile ini_of(std::string_view text)
{
    auto r = hal::ini::IniFile::parse(text, "m.ini");
    EXPECT_TRUE(r) << (r ? "" : r.error().message);
    return r ? *r : *hal::ini::IniFile::parse("", "m.ini");
}
