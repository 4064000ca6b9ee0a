// SPDX-License-Identifier: GPL-2.0-or-later
// hal_component.cpp - see hal_component.hpp.
#include "hal_component.hpp"

#include <cerrno>
#include <vector>

#include "hal_errors.hpp"
#include "hal_values.hpp"

namespace hal::py {

namespace {

// Every component created in this process, for exit_all_components().
std::vector<std::weak_ptr<CompState>>& registry()
{
    static std::vector<std::weak_ptr<CompState>> comps;
    return comps;
}

// Where a pin's value is now: its signal's value or its own, as the HAL aimed the
// pin's data pointer (hal_pin_aim stores it atomically when linking).
volatile void* pin_target(const ItemData& d)
{
    auto* ptr = static_cast<unsigned long long*>(d.storage);
    return reinterpret_cast<volatile void*>(static_cast<uintptr_t>(__atomic_load_n(ptr, __ATOMIC_ACQUIRE)));
}

volatile void* value_address(const ItemData& d)
{
    return d.is_pin ? pin_target(d) : static_cast<volatile void*>(d.storage);
}

// An input pin linked to a signal that another pin writes: the writer owns the value.
void refuse_if_driven(const ItemData& d)
{
    if (!d.is_pin || d.dir != HAL_IN)
        return;
    hal_pin_info pin{};
    if (hal_find_pin(d.name.c_str(), &pin) != 0 || !pin.signal[0])
        return;
    hal_sig_info sig{};
    if (hal_find_sig(pin.signal, &sig) == 0 && sig.writers > 0)
        throw HalError("pin '" + d.name + "' is an input linked to signal '" + pin.signal +
                       "', which has a writer: it cannot be set");
}

}  // namespace

CompState::~CompState()
{
    exit();
}

void CompState::check_alive() const
{
    if (exited)
        throw HalError("component '" + name + "' has exited");
}

void CompState::exit()
{
    if (exited || id <= 0)
        return;
    exited = true;
    items.clear();
    hal_exit(id);
}

pyb::object Item::get() const
{
    comp_->check_alive();
    return from_hal(data_->type, load_value(data_->type, value_address(*data_)));
}

void Item::set(pyb::handle value) const
{
    comp_->check_alive();
    hal_value v = to_hal(data_->type, value, std::string(data_->is_pin ? "pin" : "parameter") + " '" +
                                                 data_->name + "'");
    refuse_if_driven(*data_);
    store_value(data_->type, value_address(*data_), v);
}

Component::Component(const std::string& name, const pyb::object& prefix)
    : state_(std::make_shared<CompState>())
{
    MessageCapture capture;
    int id = hal_init(name.c_str());
    if (id < 0)
        fail(capture, id, "cannot create component '" + name + "'");
    state_->id = id;
    state_->name = name;
    state_->prefix = prefix.is_none() ? name : prefix.cast<std::string>();
    registry().push_back(state_);
}

std::shared_ptr<ItemData> Component::add_item(const std::string& name, int type, int dir, bool is_pin)
{
    state_->check_alive();
    const char* kind = is_pin ? "pin" : "parameter";
    std::string full = state_->prefix.empty() ? name : state_->prefix + "." + name;
    // As in LinuxCNC's HAL: a component's interface is fixed once it is ready.
    if (state_->ready)
        throw HalError(std::string(kind) + " '" + full + "': component '" + state_->name +
                       "' is already ready; create pins and parameters before ready(), "
                       "or call unready() first");
    MessageCapture capture;
    void* storage = hal_malloc(8);   // a pin's data pointer, or a parameter's value
    if (!storage)
        fail(capture, -ENOMEM, std::string(kind) + " '" + full + "': out of HAL memory");
    int rc = is_pin ? hal_pin_new(full.c_str(), static_cast<hal_type_t>(type),
                                  static_cast<hal_pin_dir_t>(dir), static_cast<void**>(storage), state_->id)
                    : hal_param_new(full.c_str(), static_cast<hal_type_t>(type),
                                    static_cast<hal_param_dir_t>(dir), storage, state_->id);
    if (rc < 0)
        fail(capture, rc, std::string("cannot create ") + kind + " '" + full + "'");
    auto d = std::make_shared<ItemData>(
        ItemData{full, static_cast<hal_type_t>(type), dir, is_pin, storage});
    state_->items[name] = d;
    return d;
}

Pin Component::newpin(const std::string& name, int type, int dir)
{
    return Pin(state_, add_item(name, type, dir, true));
}

Param Component::newparam(const std::string& name, int type, int dir)
{
    return Param(state_, add_item(name, type, dir, false));
}

std::shared_ptr<ItemData> Component::find(const std::string& name) const
{
    state_->check_alive();
    auto it = state_->items.find(name);
    if (it == state_->items.end())
        throw pyb::attribute_error("component '" + state_->name + "' has no pin or parameter '" + name + "'");
    return it->second;
}

pyb::object Component::getitem(const std::string& name) const
{
    return Item(state_, find(name)).get();
}

void Component::setitem(const std::string& name, pyb::handle value)
{
    Item(state_, find(name)).set(value);
}

pyb::object Component::getpin(const std::string& name) const
{
    auto d = find(name);
    if (!d->is_pin)
        throw pyb::attribute_error("'" + name + "' of component '" + state_->name + "' is a parameter, not a pin");
    return pyb::cast(Pin(state_, d));
}

pyb::object Component::getparam(const std::string& name) const
{
    auto d = find(name);
    if (d->is_pin)
        throw pyb::attribute_error("'" + name + "' of component '" + state_->name + "' is a pin, not a parameter");
    return pyb::cast(Param(state_, d));
}

pyb::dict Component::getpins() const
{
    state_->check_alive();
    pyb::dict out;
    for (const auto& [name, d] : state_->items)
        if (d->is_pin)
            out[pyb::str(name)] = pyb::cast(Pin(state_, d));
    return out;
}

void Component::ready()
{
    state_->check_alive();
    MessageCapture capture;
    int rc = hal_ready(state_->id);
    if (rc < 0)
        fail(capture, rc, "component '" + state_->name + "': ready failed");
    state_->ready = true;
}

// LinuxCNC 2.9: not ready again, so that more pins and parameters may follow; ready()
// then announces the new interface (loadusr -W, component_is_ready).
void Component::unready()
{
    state_->check_alive();
    MessageCapture capture;
    int rc = hal_unready(state_->id);
    if (rc < 0)
        fail(capture, rc, "component '" + state_->name + "': unready failed");
    state_->ready = false;
}

void Component::setprefix(const std::string& prefix)
{
    state_->check_alive();
    state_->prefix = prefix;
}

void exit_all_components()
{
    for (auto& w : registry())
        if (auto s = w.lock())
            s->exit();
    registry().clear();
}

void register_component(pyb::module_& m)
{
    pyb::class_<Item>(m, "item", "a pin or parameter of a component made by this process")
        .def("get", &Item::get, "the current value")
        .def("set", &Item::set, pyb::arg("value"), "set the value")
        .def("get_type", &Item::get_type, "HAL_BIT, HAL_FLOAT, HAL_S32, HAL_U32, HAL_S64 or HAL_U64")
        .def("get_dir", &Item::get_dir, "HAL_IN, HAL_OUT, HAL_IO (pins) or HAL_RO, HAL_RW (parameters)")
        .def("get_name", &Item::get_name, "the full HAL name, prefix included")
        .def("is_pin", &Item::is_pin, "True for a pin, False for a parameter")
        .def("__repr__", [](const Item& i) {
            return std::string(i.is_pin() ? "<hal pin \"" : "<hal param \"") + i.get_name() + "\">";
        });
    pyb::class_<Pin, Item>(m, "Pin", "a pin of a component made by this process");
    pyb::class_<Param, Item>(m, "Param", "a parameter of a component made by this process");

    pyb::class_<Component>(m, "component", pyb::dynamic_attr(),
                           "component(name, prefix=name): a userspace HAL component")
        .def(pyb::init<const std::string&, const pyb::object&>(), pyb::arg("name"),
             pyb::arg("prefix") = pyb::none())
        .def("newpin", &Component::newpin, pyb::arg("name"), pyb::arg("type"), pyb::arg("dir"),
             "newpin(name, type, dir): create pin prefix.name; returns a Pin")
        .def("newparam", &Component::newparam, pyb::arg("name"), pyb::arg("type"), pyb::arg("dir"),
             "newparam(name, type, dir): create parameter prefix.name (dir HAL_RO or HAL_RW)")
        .def("getpin", &Component::getpin, pyb::arg("name"))
        .def("getparam", &Component::getparam, pyb::arg("name"))
        .def("getpins", &Component::getpins, "dict of this component's pins by the names given to newpin")
        .def("ready", &Component::ready, "tell the HAL the component is ready (loadusr -W waits for this)")
        .def("unready", &Component::unready, "make the component not ready again, to add pins and parameters")
        .def("exit", &Component::exit, "remove the component and its pins from the HAL")
        .def("setprefix", &Component::setprefix, pyb::arg("prefix"))
        .def("getprefix", &Component::getprefix)
        .def("__getitem__", &Component::getitem)
        .def("__setitem__", &Component::setitem)
        .def("__contains__", [](const Component& c, const std::string& name) {
            try {
                c.getitem(name);
                return true;
            } catch (const pyb::attribute_error&) {
                return false;
            }
        })
        .def("__getattr__", &Component::getitem)
        .def("__setattr__", [](pyb::object self, const std::string& name, pyb::object value) {
            Component& c = self.cast<Component&>();
            try {
                c.setitem(name, value);
            } catch (const pyb::attribute_error&) {
                // not a pin or parameter: an ordinary attribute (subclasses keep state)
                pyb::module_::import("builtins").attr("object").attr("__setattr__")(self, name, value);
            }
        })
        .def_property_readonly("name", &Component::name);
}

}  // namespace hal::py
