// SPDX-License-Identifier: GPL-2.0-or-later
// hal_component.hpp - hal.component, hal.Pin and hal.Param: a userspace HAL
// component written in Python (LinuxCNC's "Creating Userspace Python Components").
// The component owns its HAL id (hal_init .. hal_exit); pin and parameter objects
// share ownership, so a Pin kept after the component object is gone still works,
// and every access after exit() raises hal.error instead of touching freed memory.
#pragma once

#include <pybind11/pybind11.h>

#include <map>
#include <memory>
#include <string>

extern "C" {
#include "hal_query.h"
}

namespace hal::py {

namespace pyb = pybind11;

// One pin or parameter this process created.
struct ItemData {
    std::string name;        // full HAL name (prefix.name)
    hal_type_t type;
    int dir;                 // hal_pin_dir_t or hal_param_dir_t
    bool is_pin;
    void* storage;           // pin: its data pointer (void **) in HAL memory; param: its value
};

struct CompState {
    int id = 0;
    std::string name;
    std::string prefix;
    bool ready = false;
    bool exited = false;
    std::map<std::string, std::shared_ptr<ItemData>> items;   // by the name given to newpin

    ~CompState();
    void check_alive() const;   // hal.error after exit()
    void exit();                // hal_exit; idempotent
};

// What hal.Pin / hal.Param wrap.
class Item {
public:
    Item(std::shared_ptr<CompState> comp, std::shared_ptr<ItemData> data)
        : comp_(std::move(comp)), data_(std::move(data)) {}
    pyb::object get() const;
    void set(pyb::handle value) const;
    int get_type() const { return data_->type; }
    int get_dir() const { return data_->dir; }
    std::string get_name() const { return data_->name; }
    bool is_pin() const { return data_->is_pin; }

private:
    std::shared_ptr<CompState> comp_;
    std::shared_ptr<ItemData> data_;
};
struct Pin : Item { using Item::Item; };
struct Param : Item { using Item::Item; };

class Component {
public:
    Component(const std::string& name, const pyb::object& prefix);
    Pin newpin(const std::string& name, int type, int dir);
    Param newparam(const std::string& name, int type, int dir);
    pyb::object getitem(const std::string& name) const;          // c["x"], c.x
    void setitem(const std::string& name, pyb::handle value);    // c["x"] = v, c.x = v
    pyb::object getpin(const std::string& name) const;
    pyb::object getparam(const std::string& name) const;
    pyb::dict getpins() const;
    void ready();
    void unready();
    void exit() { state_->exit(); }
    void setprefix(const std::string& prefix);
    std::string getprefix() const { return state_->prefix; }
    const std::string& name() const { return state_->name; }

private:
    std::shared_ptr<ItemData> find(const std::string& name) const;   // AttributeError if absent
    std::shared_ptr<ItemData> add_item(const std::string& name, int type, int dir, bool is_pin);
    std::shared_ptr<CompState> state_;
};

void register_component(pyb::module_& m);
// Called at interpreter exit (atexit): hal_exit for every component still alive.
void exit_all_components();

}  // namespace hal::py
