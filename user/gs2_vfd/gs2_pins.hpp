// SPDX-License-Identifier: GPL-2.0-or-later
// gs2_pins.hpp - gs2_vfd's pins and parameters (gs2_vfd(1) PINS, PARAMETERS), in
// hal_malloc() memory: written by the poll loop, read by halcmd and realtime code.
#pragma once

#include <string>

#include "hal.h"

namespace hal::gs2 {

struct Gs2Pins {
    // from the drive (out)
    hal_float_t *dc_bus_volts, *frequency_command, *frequency_out, *load_percentage, *motor_rpm,
        *output_current, *output_voltage, *power_factor, *scale_frequency;
    hal_bit_t *at_speed, *is_stopped;
    hal_s32_t *firmware_revision, *status_1, *status_2;
    // to the drive (in)
    hal_bit_t *err_reset, *spindle_fwd, *spindle_on, *spindle_rev;
    hal_float_t* speed_command;
    // parameters
    hal_s32_t error_count, retval, ack_delay;
    hal_float_t loop_time, nameplate_hz, nameplate_rpm, tolerance;
};

// Makes every pin and parameter "<prefix>.<name>" and sets the page's defaults.
// 0 or the negative errno of the first failing HAL call (which printed a message).
int export_gs2_pins(Gs2Pins* p, int comp_id, const std::string& prefix);

}  // namespace hal::gs2
