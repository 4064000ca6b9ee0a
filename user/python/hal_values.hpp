// SPDX-License-Identifier: GPL-2.0-or-later
// hal_values.hpp - HAL values <-> Python objects for the hal module: bits are
// bool, floats float, the integer types int. Wrong Python types raise TypeError,
// values the type cannot hold (out of range, nan for an integer) ValueError.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

extern "C" {
#include "hal_query.h"
}

namespace hal::py {

namespace pyb = pybind11;

// 'what' names the pin/param/signal for the error message.
hal_value to_hal(hal_type_t type, pyb::handle obj, const std::string& what);
pyb::object from_hal(hal_type_t type, const hal_value& v);

// Load / store a value of 'type' at 'addr' (a pin's target or a parameter's
// storage in the HAL segment), without tearing 64-bit values.
hal_value load_value(hal_type_t type, const volatile void* addr);
void store_value(hal_type_t type, volatile void* addr, const hal_value& v);

bool type_valid(int type);

}  // namespace hal::py
