// SPDX-License-Identifier: GPL-2.0-or-later
// inihal.cpp - see inihal.hpp.
#include "inihal.hpp"

#include <cerrno>
#include <cstring>

#include "hal.h"
#include "hal_query.h"

namespace hal::task {

Result<std::unique_ptr<IniHal>> IniHal::create(int comp_id, const TaskConfig& cfg)
{
    std::unique_ptr<IniHal> h(new IniHal);
    h->items_ = inihal_items(cfg);
    h->pins_ = static_cast<PinPtr*>(hal_malloc(static_cast<long>(h->items_.size() * sizeof(PinPtr))));
    if (!h->pins_)
        return Error{-ENOMEM, "inihal: out of HAL memory for " + std::to_string(h->items_.size()) + " pins"};
    for (size_t i = 0; i < h->items_.size(); ++i) {
        const IniItem& it = h->items_[i];
        double v = it.get(cfg);
        int rc = 0;
        // IN pins: a HAL file may net them or setp them
        switch (it.type) {
        case IniPinType::Float:
            rc = hal_pin_float_newf(HAL_IN, &h->pins_[i].f, comp_id, "%s",
                                    it.name.c_str());
            if (!rc)
                *h->pins_[i].f = v;
            break;
        case IniPinType::S32:
            rc = hal_pin_s32_newf(HAL_IN, &h->pins_[i].s, comp_id, "%s",
                                  it.name.c_str());
            if (!rc)
                *h->pins_[i].s = static_cast<int>(v);
            break;
        case IniPinType::Bit:
            rc = hal_pin_bit_newf(HAL_IN, &h->pins_[i].b, comp_id, "%s",
                                  it.name.c_str());
            if (!rc)
                *h->pins_[i].b = v != 0;
            break;
        }
        if (rc)
            return Error{rc, "inihal: cannot create pin " + it.name + ": " + std::strerror(-rc)};
    }
    return h;
}

std::vector<motion_command> IniHal::poll(TaskConfig& cfg)
{
    std::vector<double> values(items_.size());
    for (size_t i = 0; i < items_.size(); ++i) {
        switch (items_[i].type) {
        case IniPinType::Float: values[i] = *pins_[i].f; break;
        case IniPinType::S32: values[i] = *pins_[i].s; break;
        case IniPinType::Bit: values[i] = *pins_[i].b ? 1 : 0; break;
        }
    }
    return inihal_apply(items_, values, cfg);
}

static double as_double(hal_type_t type, const union hal_value& v)
{
    switch (type) {
    case HAL_BIT: return v.b ? 1 : 0;
    case HAL_FLOAT: return v.f;
    case HAL_S32: return v.s;
    case HAL_U32: return v.u;
    case HAL_S64: return static_cast<double>(v.ls);
    case HAL_U64: return static_cast<double>(v.lu);
    default: return 0;
    }
}

bool read_hal_value(const std::string& name, double& value)
{
    struct hal_pin_info pin;
    if (hal_find_pin(name.c_str(), &pin) == 0) {
        value = as_double(pin.type, pin.value);
        return true;
    }
    struct hal_sig_info sig;
    if (hal_find_sig(name.c_str(), &sig) == 0) {
        value = as_double(sig.type, sig.value);
        return true;
    }
    struct hal_param_info par;
    if (hal_find_param(name.c_str(), &par) == 0) {
        value = as_double(par.type, par.value);
        return true;
    }
    return false;
}

}  // namespace hal::task
