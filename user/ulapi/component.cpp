// SPDX-License-Identifier: GPL-2.0-or-later
// component.cpp - hal::Component, the RAII wrapper of hal_init/hal_ready/hal_exit.
#include "hal/component.hpp"

#include <cstring>

extern "C" {
#include "hal.h"
}

namespace hal {

Result<Component> Component::create(const std::string& name)
{
    int id = hal_init(name.c_str());
    if (id < 0)
        return Error{id, "cannot create component '" + name + "': " + std::strerror(-id)};
    return Component{id};
}

Component& Component::operator=(Component&& other) noexcept
{
    if (this != &other) {
        if (id_ > 0)
            hal_exit(id_);
        id_ = other.id_;
        other.id_ = 0;
    }
    return *this;
}

Component::~Component()
{
    if (id_ > 0)
        hal_exit(id_);
}

Result<void> Component::ready()
{
    int rc = hal_ready(id_);
    if (rc < 0)
        return Error{rc, std::string("hal_ready failed: ") + std::strerror(-rc)};
    return {};
}

}  // namespace hal
