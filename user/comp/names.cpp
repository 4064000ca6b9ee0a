// SPDX-License-Identifier: GPL-2.0-or-later
// names.cpp - see names.hpp.
#include "names.hpp"

#include <cstdio>

namespace hal::comp {

std::string to_hal(const std::string& name)
{
    std::string out;
    for (char c : name)
        out += c == '_' ? '-' : c;
    while (!out.empty() && (out.back() == '-' || out.back() == '.'))
        out.pop_back();
    return out;
}

std::string to_hal_format(const std::string& name)
{
    std::string hal = to_hal(name), out;
    for (std::size_t i = 0; i < hal.size();) {
        if (hal[i] != '#') {
            out += hal[i] == '%' ? "%%" : std::string(1, hal[i]);
            ++i;
            continue;
        }
        std::size_t n = 0;
        while (i < hal.size() && hal[i] == '#')
            ++n, ++i;
        out += "%0" + std::to_string(n) + "d";
    }
    return out;
}

std::string to_c(const std::string& name)
{
    std::string out;
    for (std::size_t i = 0; i < name.size(); ++i) {
        char c = name[i];
        if (c == '#') {
            while (!out.empty() && out.back() == '_')  // separators before the block
                out.pop_back();
            while (i + 1 < name.size() && name[i + 1] == '#')
                ++i;
            continue;
        }
        if (c == '-' || c == '.')
            c = '_';
        if (c == '_' && !out.empty() && out.back() == '_')
            continue;
        out += c;
    }
    return out;
}

int hash_blocks(const std::string& name)
{
    int blocks = 0;
    for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '#' && (i == 0 || name[i - 1] != '#'))
            ++blocks;
    return blocks;
}

std::string c_quote(const std::string& text)
{
    std::string out = "\"";
    for (unsigned char c : text) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\t': out += "\\t"; break;
        default:
            if (c < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof(buf), "\\%03o", c);
                out += buf;
            } else {
                out += static_cast<char>(c);
            }
        }
    }
    return out + "\"";
}

}  // namespace hal::comp
