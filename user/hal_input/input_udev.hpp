// SPDX-License-Identifier: GPL-2.0-or-later
// input_udev.hpp - the evdev devices present now, found through libudev (name, phys
// and id from the parent input device's sysfs attributes).
#pragma once

#include <vector>

#include "input_spec.hpp"

namespace hal::input {

std::vector<DeviceInfo> scan_input_devices();

}  // namespace hal::input
