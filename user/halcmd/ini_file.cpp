// SPDX-License-Identifier: GPL-2.0-or-later
// ini_file.cpp - see ini_file.hpp.
#include "ini_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace hal::halcmd {

static std::string_view trim(std::string_view s)
{
    size_t b = s.find_first_not_of(" \t\r\n");
    if (b == std::string_view::npos)
        return {};
    size_t e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
}

Result<IniFile> IniFile::load(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
        return Error{-errno, "cannot open inifile '" + path + "': " + std::strerror(errno)};
    std::stringstream ss;
    ss << in.rdbuf();
    return parse(ss.str(), path);
}

IniFile IniFile::parse(std::string_view text, std::string path)
{
    IniFile ini;
    ini.path_ = std::move(path);
    std::string section;
    while (!text.empty()) {
        size_t nl = text.find('\n');
        std::string_view line = trim(text.substr(0, nl));
        text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
        if (line.empty() || line[0] == '#' || line[0] == ';')
            continue;
        if (line[0] == '[') {
            size_t close = line.find(']');
            if (close != std::string_view::npos)
                section = std::string(trim(line.substr(1, close - 1)));
            continue;
        }
        size_t eq = line.find('=');
        if (eq == std::string_view::npos)
            continue;                    // not a KEY = VALUE line: ignored, as inifile readers do
        std::string key(trim(line.substr(0, eq)));
        std::string value(trim(line.substr(eq + 1)));
        ini.values_.emplace(std::make_pair(section, key), value);   // emplace keeps the first
    }
    return ini;
}

std::optional<std::string> IniFile::get(std::string_view section, std::string_view key) const
{
    auto it = values_.find(std::make_pair(std::string(section), std::string(key)));
    if (it == values_.end())
        return std::nullopt;
    return it->second;
}

}  // namespace hal::halcmd
