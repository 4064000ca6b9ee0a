// SPDX-License-Identifier: GPL-2.0-or-later
// gen_c.hpp - turns a Component into the C source of a HAL module (realtime, for
// both flavors: only rtapi.h, rtapi_app.h, hal.h, rtapi_math.h) or, with option
// userspace, of a userspace component program.
#pragma once

#include <string>

#include "model.hpp"

namespace hal::comp {

inline constexpr int kMaxInstances = 64;  // size of names=/personality=
inline constexpr int kMaxCount = 100000;  // count= limit (benchmarks load 16,000 and2)

std::string generate_c(const Component& c);

// IEEE-754 bits of a default value if it is a plain number ("1.5", "-2", "1e-3"),
// so init code can store float defaults without FP instructions (kernel init runs
// outside FPU sections). Returns false for names such as M_PI.
bool float_bits(const std::string& value, unsigned long long* bits);

}  // namespace hal::comp
