// SPDX-License-Identifier: GPL-2.0-or-later
// input_axes.hpp - hal_input(1)'s axis arithmetic, pure so the unit tests can check
// it: absolute axes with fuzz, flat, scale and offset; relative axes with precision,
// reset and the "absolute" duplicate filter.
#pragma once

#include <cstdint>

namespace hal::input {

// Default scale and offset map [min, max] to [-1, 1].
struct AbsDefaults {
    double scale, offset;
};
AbsDefaults abs_defaults(int32_t min, int32_t max);

// New counts for a device value: within 'flat' of offset reads as offset; otherwise
// counts moves only when the value differs from it by at least 'fuzz'.
int32_t abs_counts(int32_t counts, int32_t value, double offset, int32_t fuzz, int32_t flat);
double abs_position(int32_t counts, double offset, double scale);

// A relative event's value as a signed number of 'precision' bits (1..32, clamped).
int32_t rel_sign_extend(int32_t value, int32_t precision);

struct RelState {
    int32_t counts = 0;
    int32_t last = 0;              // the "last" parameter
};
// Applies one event. With 'absolute' set, a value equal to 'last' is a repeat and ignored.
void rel_event(RelState& s, int32_t value, int32_t precision, bool absolute);
double rel_position(int32_t counts, double scale);

}  // namespace hal::input
