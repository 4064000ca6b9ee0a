// SPDX-License-Identifier: GPL-2.0-or-later
// tooltable.cpp - reading and writing the tool table file (see tooltable.hpp).
#include "tooltable.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>

#include "hal/numbers.hpp"
#include "ini/axes.hpp"

namespace hal::io {

using hal::ini::AXIS_LETTERS;

static bool parse_int(const std::string& s, int& v)
{
    long l = 0;
    if (!parse_integer(s, l, -2147483647L, 2147483647L))
        return false;
    v = static_cast<int>(l);
    return true;
}

Result<std::optional<Tool>> parse_tool_line(const std::string& raw)
{
    if (raw.size() > TOOL_LINE_MAX)
        return Error{-1, "line longer than " + std::to_string(TOOL_LINE_MAX) + " characters"};
    std::string line = raw;
    if (!line.empty() && line.back() == '\r')
        line.pop_back();
    Tool t;
    size_t semi = line.find(';');
    if (semi != std::string::npos) {
        t.comment = line.substr(semi + 1);
        line.erase(semi);
    }
    bool any = false, have_p = false;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
            ++i;
        if (i >= line.size())
            break;
        size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t')
            ++j;
        std::string word = line.substr(i, j - i);
        i = j;
        any = true;
        char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(word[0])));
        std::string value = word.substr(1);
        const char* ax = std::strchr(AXIS_LETTERS, letter);
        bool good = true;
        if (letter == 'T') {
            good = parse_int(value, t.toolno) && t.toolno >= 0;
        } else if (letter == 'P') {
            good = parse_int(value, t.pocket) && t.pocket >= 0 && t.pocket < POCKETS_MAX;
            have_p = true;
        } else if (ax && letter != '\0') {
            good = parse_finite(value, t.offset[ax - AXIS_LETTERS]);
        } else if (letter == 'D') {
            good = parse_finite(value, t.diameter);
        } else if (letter == 'I') {
            good = parse_finite(value, t.frontangle);
        } else if (letter == 'J') {
            good = parse_finite(value, t.backangle);
        } else if (letter == 'Q') {
            good = parse_int(value, t.orientation) && t.orientation >= 0 && t.orientation <= 9;
        } else {
            return Error{-1, "unknown field '" + word + "'"};
        }
        if (!good)
            return Error{-1, "bad value in '" + word + "'"};
    }
    if (!any)
        return std::optional<Tool>();   // blank or remark-only line
    if (t.toolno < 0)
        return Error{-1, "no tool number (T)"};
    if (!have_p)
        return Error{-1, "no pocket (P) for tool " + std::to_string(t.toolno)};
    return std::optional<Tool>(t);
}

std::string format_tool(const Tool& t)
{
    char buf[64];
    std::string s = "T" + std::to_string(t.toolno) + " P" + std::to_string(t.pocket);
    for (int k = 0; k < 9; ++k)
        if (t.offset[k] != 0) {
            std::snprintf(buf, sizeof buf, " %c%+f", AXIS_LETTERS[k], t.offset[k]);
            s += buf;
        }
    if (t.diameter != 0) {
        std::snprintf(buf, sizeof buf, " D%+f", t.diameter);
        s += buf;
    }
    if (t.frontangle != 0) {
        std::snprintf(buf, sizeof buf, " I%+f", t.frontangle);
        s += buf;
    }
    if (t.backangle != 0) {
        std::snprintf(buf, sizeof buf, " J%+f", t.backangle);
        s += buf;
    }
    if (t.orientation != 0)
        s += " Q" + std::to_string(t.orientation);
    if (!t.comment.empty())
        s += " ;" + t.comment;
    return s;
}

Result<std::vector<Tool>> read_tool_file(const std::string& path)
{
    std::ifstream f(path);
    if (!f)
        return Error{-errno, path + ": cannot open tool table: " + std::strerror(errno)};
    std::vector<Tool> tools;
    std::set<int> seen;
    std::string line;
    int n = 0;
    while (std::getline(f, line)) {
        ++n;
        auto t = parse_tool_line(line);
        if (!t)
            return Error{-1, path + ":" + std::to_string(n) + ": " + t.error().message};
        if (!*t)
            continue;
        if (!seen.insert((*t)->toolno).second)
            return Error{-1, path + ":" + std::to_string(n) + ": tool " + std::to_string((*t)->toolno) +
                                 " appears twice"};
        tools.push_back(**t);
    }
    return tools;
}

Result<void> write_tool_file(const std::string& path, const std::vector<Tool>& tools)
{
    std::string tmp = path + ".tmp";
    {
        std::ofstream f(tmp, std::ios::trunc);
        if (!f)
            return Error{-errno, path + ": cannot write tool table: " + std::strerror(errno)};
        for (const Tool& t : tools)
            if (t.toolno >= 0)
                f << format_tool(t) << '\n';
        f.flush();
        if (!f)
            return Error{-EIO, path + ": write error"};
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
        return Error{-errno, path + ": cannot replace tool table: " + std::strerror(errno)};
    return ok();
}

}  // namespace hal::io
