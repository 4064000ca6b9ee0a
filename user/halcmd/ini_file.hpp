// SPDX-License-Identifier: GPL-2.0-or-later
// ini_file.hpp - the small inifile reader behind "halcmd -i": [SECTION] headers and
// KEY = VALUE lines; '#' and ';' start comment lines. The first definition wins.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "hal/result.hpp"

namespace hal::halcmd {

class IniFile {
public:
    static Result<IniFile> load(const std::string& path);
    static IniFile parse(std::string_view text, std::string path);

    std::optional<std::string> get(std::string_view section, std::string_view key) const;
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::map<std::pair<std::string, std::string>, std::string, std::less<>> values_;
};

}  // namespace hal::halcmd
