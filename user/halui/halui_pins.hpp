// SPDX-License-Identifier: GPL-2.0-or-later
// halui_pins.hpp - the halui.* HAL pins (emcrsh-and-halui.md 3.2, LinuxCNC 2.9
// names) bound to the fields of halui_core's Inputs/Outputs, with every differing
// EMC2 2.4 name of the seed halui(1) page as an alias of the same pin (3.3), so
// EMC2-era .hal files load.
#pragma once

#include <string>
#include <vector>

#include "hal.h"
#include "halui_core.hpp"

namespace hal::halui {

class Pins {
public:
    // Creates every pin of the configuration for component comp_id; 'in' and 'out'
    // (sized by Core::make_inputs/make_outputs) must outlive the pins. IN pins start
    // at the fields' defaults (count-enable TRUE, scale 0.1, jog-deadband 0.2). On
    // failure: -errno, and 'error' names the pin.
    int create(int comp_id, const Config& cfg, Inputs& in, Outputs& out, std::string& error);
    void read();          // IN pins -> Inputs
    void write() const;   // Outputs -> OUT pins

    size_t count() const { return pins_.size(); }

private:
    struct Binding {
        hal_type_t type;
        hal_pin_dir_t dir;
        void** pin;      // the pin's data pointer (a slot in HAL shared memory)
        void* field;     // bool, double, int32_t or unsigned in Inputs/Outputs
    };
    int add(hal_type_t type, hal_pin_dir_t dir, void* field, const std::string& name,
            const std::vector<std::string>& aliases = {});

    int comp_id_ = 0;
    void** slots_ = nullptr;
    size_t slots_left_ = 0;
    std::vector<Binding> pins_;
    std::string error_;
};

}  // namespace hal::halui
