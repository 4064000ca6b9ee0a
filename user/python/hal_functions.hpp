// SPDX-License-Identifier: GPL-2.0-or-later
// hal_functions.hpp - the hal module's functions (hal_functions.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace hal::py {

void register_functions(pybind11::module_& m);

}  // namespace hal::py
