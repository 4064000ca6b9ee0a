// SPDX-License-Identifier: GPL-2.0-or-later
// number_arg.hpp - a command-line number for the path-check helpers
// (motion_pathcheck, toolpath_check): the whole argument must be a finite number,
// otherwise "PROG: 'ARG' is not a number" and exit 2 (bad usage).
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>

inline double number_arg(const char* prog, const char* s)
{
    char* end = nullptr;
    double v = std::strtod(s, &end);
    if (end == s || *end != '\0' || !std::isfinite(v)) {
        std::fprintf(stderr, "%s: '%s' is not a number\n", prog, s);
        std::exit(2);
    }
    return v;
}
