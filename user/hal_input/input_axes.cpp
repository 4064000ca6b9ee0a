// SPDX-License-Identifier: GPL-2.0-or-later
// input_axes.cpp - see input_axes.hpp.
#include "input_axes.hpp"

#include <cmath>

namespace hal::input {

AbsDefaults abs_defaults(int32_t min, int32_t max)
{
    double half = (static_cast<double>(max) - static_cast<double>(min)) / 2;
    return {half != 0 ? half : 1.0, (static_cast<double>(max) + static_cast<double>(min)) / 2};
}

int32_t abs_counts(int32_t counts, int32_t value, double offset, int32_t fuzz, int32_t flat)
{
    if (flat > 0 && std::fabs(value - offset) < flat)
        value = static_cast<int32_t>(std::lround(offset));
    int64_t diff = static_cast<int64_t>(value) - counts;
    if (fuzz > 0 && diff != 0 && (diff < 0 ? -diff : diff) < fuzz && value != std::lround(offset))
        return counts;
    return value;
}

double abs_position(int32_t counts, double offset, double scale)
{
    return scale != 0 ? (counts - offset) / scale : 0.0;
}

int32_t rel_sign_extend(int32_t value, int32_t precision)
{
    if (precision < 1)
        precision = 1;
    if (precision >= 32)
        return value;
    uint32_t mask = (1u << precision) - 1;
    uint32_t v = static_cast<uint32_t>(value) & mask;
    if (v & (1u << (precision - 1)))
        v |= ~mask;
    return static_cast<int32_t>(v);
}

void rel_event(RelState& s, int32_t value, int32_t precision, bool absolute)
{
    if (absolute && value == s.last)
        return;
    s.last = value;
    s.counts += rel_sign_extend(value, precision);
}

double rel_position(int32_t counts, double scale)
{
    return scale != 0 ? counts / scale : 0.0;
}

}  // namespace hal::input
