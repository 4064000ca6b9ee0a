// SPDX-License-Identifier: GPL-2.0-or-later
// meter_source.hpp - what halmeter reads: the current value of a pin, signal or
// parameter, formatted as halcmd prints it, and the names offered by the Select
// dialog. Reads go through hal_find_*(), which copy the value with one aligned load
// (64-bit values never tear) and take only the configuration mutex, which realtime
// threads never take: halmeter cannot delay realtime code.
#pragma once

#include <string>
#include <vector>

#include "hal/result.hpp"
#include "meter_options.hpp"

namespace hal::meter {

// Attach to the running HAL (no component is created). One error line if none runs.
Result<void> attach_hal();

// The item's value as text ("TRUE", "-12", "0.25"), or an error naming the item.
Result<std::string> read_item(const Item& item);

// Sorted names of every pin, signal or parameter.
std::vector<std::string> list_names(Kind kind);

}  // namespace hal::meter
