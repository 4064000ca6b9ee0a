// SPDX-License-Identifier: GPL-2.0-or-later
// numbers.hpp - a whole word as a number, as bus commands, emcrsh lines and tool-table
// fields give them: nothing before or after it, finite, in range. One rule for every
// tool, so "1.5x", "", "nan" and an overflow are refused alike.
#pragma once

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <string>

namespace hal {

// the whole of `s` is a finite number (strtod's forms); `out` is unchanged otherwise
inline bool parse_finite(const std::string& s, double& out)
{
    if (s.empty())
        return false;
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(s.c_str(), &end);
    if (*end != '\0' || errno != 0 || !std::isfinite(v))
        return false;
    out = v;
    return true;
}

// the whole of `s` is a decimal integer in lo..hi; `out` is unchanged otherwise
inline bool parse_integer(const std::string& s, long& out, long lo = LONG_MIN, long hi = LONG_MAX)
{
    if (s.empty())
        return false;
    char* end = nullptr;
    errno = 0;
    long v = std::strtol(s.c_str(), &end, 10);
    if (*end != '\0' || errno != 0 || v < lo || v > hi)
        return false;
    out = v;
    return true;
}

}   // namespace hal
