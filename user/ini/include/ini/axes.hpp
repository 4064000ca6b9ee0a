// SPDX-License-Identifier: GPL-2.0-or-later
// axes.hpp - the nine axis letters in their fixed order (X=0 ... W=8), as [TRAJ]COORDINATES,
// [AXIS_L] sections, tool-table offsets, the interpreter's words and axis.L.* pins use them.
// One table, so every tool numbers the axes the same way.
#pragma once

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

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

// "1.5 -2 0", one number per letter of `letters` (task's traj.axes: the configured axes,
// X..W order), into out[axis] (AXIS_COUNT entries); the axes not listed keep their
// value, a non-finite number is 0, and the first word that is not a number ends it.
inline void values_by_axis(const std::string& letters, const char* text, double* out)
{
    for (char letter : letters) {
        char* end = nullptr;
        double v = std::strtod(text, &end);
        if (end == text)
            return;
        text = end;
        int a = axis_index(letter);
        if (a >= 0)
            out[a] = std::isfinite(v) ? v : 0;
    }
}

}   // namespace hal::ini
