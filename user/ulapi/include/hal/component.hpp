// SPDX-License-Identifier: GPL-2.0-or-later
// component.hpp - RAII handle for a userspace HAL component: hal_init() in
// create(), hal_exit() in the destructor, so no exit path leaks a component.
#pragma once

#include <string>

#include "hal/result.hpp"

namespace hal {

class Component {
public:
    static Result<Component> create(const std::string& name);
    Component(Component&& other) noexcept : id_(other.id_) { other.id_ = 0; }
    Component& operator=(Component&& other) noexcept;
    Component(const Component&) = delete;
    Component& operator=(const Component&) = delete;
    ~Component();

    int id() const { return id_; }
    Result<void> ready();

private:
    explicit Component(int id) : id_(id) {}
    int id_ = 0;
};

}  // namespace hal
