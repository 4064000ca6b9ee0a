// SPDX-License-Identifier: GPL-2.0-or-later
// tooltable.hpp - the tool table file (emcrsh-and-halui.md 2.5): one tool per line,
// letter+value fields in any order (T and P required), ";remark" kept and written
// back; lines starting with ';' and blank lines ignored. HAL-free for unit tests.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "hal/result.hpp"

namespace hal::io {

constexpr int POCKETS_MAX = 1001;   // CANON_POCKETS_MAX: pockets 1..1000, 0 = spindle
constexpr size_t TOOL_LINE_MAX = 256;

struct Tool {
    int toolno = -1;                    // -1: empty entry
    int pocket = 0;
    std::array<double, 9> offset{};     // X Y Z A B C U V W
    double diameter = 0;
    double frontangle = 0;
    double backangle = 0;
    int orientation = 0;
    std::string comment;                // without the ';'
};

// One line: a tool, nullopt for a blank or comment line, or an error naming the field.
Result<std::optional<Tool>> parse_tool_line(const std::string& line);
// "T1 P1 Z+0.511000 D+0.125000 ;1/8 end mill": T and P, then the non-zero fields.
std::string format_tool(const Tool& t);

// Every tool of a file in file order; errors are "FILE:LINE: reason".
Result<std::vector<Tool>> read_tool_file(const std::string& path);
// Writes through FILE.tmp + rename, so a crash never leaves half a table.
Result<void> write_tool_file(const std::string& path, const std::vector<Tool>& tools);

}  // namespace hal::io
