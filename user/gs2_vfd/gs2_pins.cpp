// SPDX-License-Identifier: GPL-2.0-or-later
// gs2_pins.cpp - export_gs2_pins(); names exactly as gs2_vfd(1) lists them.
#include "gs2_pins.hpp"

namespace hal::gs2 {

int export_gs2_pins(Gs2Pins* p, int id, const std::string& prefix)
{
    const char* n = prefix.c_str();
    struct FloatPin { hal_float_t** ptr; hal_pin_dir_t dir; const char* name; };
    struct BitPin { hal_bit_t** ptr; hal_pin_dir_t dir; const char* name; };
    struct S32Pin { hal_s32_t** ptr; const char* name; };
    const FloatPin floats[] = {
        {&p->dc_bus_volts, HAL_OUT, "DC-bus-volts"},     {&p->frequency_command, HAL_OUT, "frequency-command"},
        {&p->frequency_out, HAL_OUT, "frequency-out"},   {&p->load_percentage, HAL_OUT, "load-percentage"},
        {&p->motor_rpm, HAL_OUT, "motor-RPM"},           {&p->output_current, HAL_OUT, "output-current"},
        {&p->output_voltage, HAL_OUT, "output-voltage"}, {&p->power_factor, HAL_OUT, "power-factor"},
        {&p->scale_frequency, HAL_OUT, "scale-frequency"}, {&p->speed_command, HAL_IN, "speed-command"},
    };
    const BitPin bits[] = {
        {&p->at_speed, HAL_OUT, "at-speed"},  {&p->is_stopped, HAL_OUT, "is-stopped"},
        {&p->err_reset, HAL_IN, "err-reset"}, {&p->spindle_fwd, HAL_IN, "spindle-fwd"},
        {&p->spindle_on, HAL_IN, "spindle-on"}, {&p->spindle_rev, HAL_IN, "spindle-rev"},
    };
    const S32Pin s32s[] = {
        {&p->firmware_revision, "firmware-revision"}, {&p->status_1, "status-1"}, {&p->status_2, "status-2"},
    };
    int rc = 0;
    for (const FloatPin& f : floats)
        if (!rc)
            rc = hal_pin_float_newf(f.dir, f.ptr, id, "%s.%s", n, f.name);
    for (const BitPin& b : bits)
        if (!rc)
            rc = hal_pin_bit_newf(b.dir, b.ptr, id, "%s.%s", n, b.name);
    for (const S32Pin& s : s32s)
        if (!rc)
            rc = hal_pin_s32_newf(HAL_OUT, s.ptr, id, "%s.%s", n, s.name);
    if (!rc)
        rc = hal_param_s32_newf(HAL_RW, &p->error_count, id, "%s.error-count", n);
    if (!rc)
        rc = hal_param_float_newf(HAL_RW, &p->loop_time, id, "%s.loop-time", n);
    if (!rc)
        rc = hal_param_float_newf(HAL_RW, &p->nameplate_hz, id, "%s.nameplate-HZ", n);
    if (!rc)
        rc = hal_param_float_newf(HAL_RW, &p->nameplate_rpm, id, "%s.nameplate-RPM", n);
    if (!rc)
        rc = hal_param_s32_newf(HAL_RW, &p->retval, id, "%s.retval", n);
    if (!rc)
        rc = hal_param_float_newf(HAL_RW, &p->tolerance, id, "%s.tolerance", n);
    if (!rc)
        rc = hal_param_s32_newf(HAL_RW, &p->ack_delay, id, "%s.ack-delay", n);
    if (rc)
        return rc;
    p->error_count = 0;
    p->retval = 0;
    p->loop_time = 0.1;
    p->nameplate_hz = 60;
    p->nameplate_rpm = 1730;
    p->tolerance = 0.01;
    p->ack_delay = 2;
    return 0;
}

}  // namespace hal::gs2
