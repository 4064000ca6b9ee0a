// SPDX-License-Identifier: GPL-2.0-or-later
// axes.hpp - the nine axis letters in their fixed order (X=0 ... W=8), as [TRAJ]COORDINATES,
// [AXIS_L] sections, tool-table offsets, the interpreter's words and axis.L.* pins use them.
// One table, so every tool numbers the axes the same way.
#pragma once

#include <cctype>
#include <cstring>

namespace hal::ini {

inline constexpr char AXIS_LETTERS[] = "XYZABCUVW";
inline constexpr int AXIS_COUNT = 9;

// index of axis letter `c` (either case), or -1 for anything else ('\0' included)
inline int axis_index(char c)
{
    char up = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const char* p = up ? std::strchr(AXIS_LETTERS, up) : nullptr;
    return p ? static_cast<int>(p - AXIS_LETTERS) : -1;
}

// the lower-case letter of axis `i` (0..8), as HAL names spell it (axis.x.*)
inline char axis_lower(int i) { return static_cast<char>(AXIS_LETTERS[i] - 'A' + 'a'); }

}   // namespace hal::ini
