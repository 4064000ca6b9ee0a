// SPDX-License-Identifier: GPL-2.0-or-later
// inihal.hpp - the HAL side of task: the `inihal` component's ini.* pins
// (inihal_items.hpp) and reading HAL values by name for #<_hal[...]>.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "hal.h"
#include "hal/result.hpp"
#include "inihal_items.hpp"

namespace hal::task {

class IniHal {
public:
    // Creates the pins on component comp_id with the configuration's values.
    static Result<std::unique_ptr<IniHal>> create(int comp_id, const TaskConfig& cfg);
    // Pins changed since the last call: stored in cfg, the motion commands returned.
    std::vector<motion_command> poll(TaskConfig& cfg);

private:
    union PinPtr {
        hal_float_t* f;
        hal_s32_t* s;
        hal_bit_t* b;
    };
    std::vector<IniItem> items_;
    PinPtr* pins_ = nullptr;   // in HAL memory, one per item
};

// A pin's, signal's or parameter's value by name (bits 0/1); false if there is none.
bool read_hal_value(const std::string& name, double& value);

}  // namespace hal::task
