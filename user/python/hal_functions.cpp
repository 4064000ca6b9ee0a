// SPDX-License-Identifier: GPL-2.0-or-later
// hal_functions.cpp - the hal module's functions for scripts (LinuxCNC's names):
// values by name (get_value, set_p, set_s), signals (new_sig, connect,
// disconnect), questions (component_exists, component_is_ready, pin_has_writer)
// and the get_info_* listings. They work on the whole HAL, like halcmd, so the
// process attaches to the HAL segment on first use; no component is needed.
#include "hal_functions.hpp"

#include <algorithm>
#include <cerrno>
#include <vector>

#include "hal_errors.hpp"
#include "hal_values.hpp"
#include "values.hpp"   // halcmd's parser: set_p/set_s take what setp/sets take

namespace hal::py {

namespace {

void attach()
{
    MessageCapture capture;
    int rc = hal_attach();
    if (rc < 0)
        fail(capture, rc, "cannot attach to the HAL");
}

template <typename Info>
std::vector<Info> all_of(int (*query)(int (*)(const Info*, void*), void*))
{
    attach();
    std::vector<Info> out;
    MessageCapture capture;
    int rc = query([](const Info* i, void* ctx) {
        static_cast<std::vector<Info>*>(ctx)->push_back(*i);
        return 0;
    }, &out);
    if (rc < 0)
        fail(capture, rc, "cannot list the HAL");
    std::sort(out.begin(), out.end(), [](const Info& a, const Info& b) {
        return std::string_view(a.name) < std::string_view(b.name);
    });
    return out;
}

// set_p/set_s take a string as halcmd does; numbers and bools are accepted too.
std::string value_text(pyb::handle value)
{
    if (PyBool_Check(value.ptr()))
        return value.ptr() == Py_True ? "1" : "0";
    if (PyUnicode_Check(value.ptr()) || PyLong_Check(value.ptr()))
        return pyb::str(value).cast<std::string>();
    if (PyFloat_Check(value.ptr()))
        return pyb::repr(value).cast<std::string>();   // all digits: 0.1 stays 0.1
    throw pyb::type_error("expected a string or a number, got " + std::string(Py_TYPE(value.ptr())->tp_name));
}

hal_value parse_or_raise(hal_type_t type, pyb::handle value, const std::string& what)
{
    auto v = hal::halcmd::parse_value(type, value_text(value));
    if (!v)
        throw pyb::value_error(what + ": " + v.error().message);
    return *v;
}

std::optional<hal_type_t> type_arg(int type)
{
    if (!type_valid(type))
        return std::nullopt;
    return static_cast<hal_type_t>(type);
}

pyb::object get_value(const std::string& name)
{
    attach();
    hal_pin_info pin{};
    if (hal_find_pin(name.c_str(), &pin) == 0)
        return from_hal(pin.type, pin.value);
    hal_param_info param{};
    if (hal_find_param(name.c_str(), &param) == 0)
        return from_hal(param.type, param.value);
    hal_sig_info sig{};
    if (hal_find_sig(name.c_str(), &sig) == 0)
        return from_hal(sig.type, sig.value);
    throw HalError("'" + name + "' is not a pin, parameter or signal");
}

void set_p(const std::string& name, pyb::handle value)
{
    attach();
    hal_pin_info pin{};
    hal_param_info param{};
    MessageCapture capture;
    if (hal_find_pin(name.c_str(), &pin) == 0) {
        hal_value v = parse_or_raise(pin.type, value, "pin '" + name + "'");
        if (int rc = hal_set_pin_value(name.c_str(), &v); rc < 0)
            fail(capture, rc, "pin '" + name + "'");
        return;
    }
    if (hal_find_param(name.c_str(), &param) == 0) {
        hal_value v = parse_or_raise(param.type, value, "parameter '" + name + "'");
        if (int rc = hal_set_param_value(name.c_str(), &v); rc < 0)
            fail(capture, rc, "parameter '" + name + "'");
        return;
    }
    throw HalError("pin or parameter '" + name + "' does not exist");
}

void set_s(const std::string& name, pyb::handle value)
{
    attach();
    hal_sig_info sig{};
    MessageCapture capture;
    if (hal_find_sig(name.c_str(), &sig) != 0)
        throw HalError("signal '" + name + "' does not exist");
    hal_value v = parse_or_raise(sig.type, value, "signal '" + name + "'");
    if (int rc = hal_set_sig_value(name.c_str(), &v); rc < 0)
        fail(capture, rc, "signal '" + name + "'");
}

void new_sig(const std::string& name, int type)
{
    auto t = type_arg(type);
    if (!t)
        throw pyb::value_error("signal '" + name + "': invalid type " + std::to_string(type) +
                               " (use hal.HAL_BIT, HAL_FLOAT, HAL_S32, HAL_U32, HAL_S64 or HAL_U64)");
    attach();
    MessageCapture capture;
    if (int rc = hal_signal_new(name.c_str(), *t); rc < 0)
        fail(capture, rc, "cannot create signal '" + name + "'");
}

void connect(const std::string& pin, const std::string& sig)
{
    attach();
    MessageCapture capture;
    if (int rc = hal_link(pin.c_str(), sig.c_str()); rc < 0)
        fail(capture, rc, "cannot link pin '" + pin + "' to signal '" + sig + "'");
}

void disconnect(const std::string& pin)
{
    attach();
    hal_pin_info info{};
    if (hal_find_pin(pin.c_str(), &info) != 0)
        throw HalError("pin '" + pin + "' does not exist");
    MessageCapture capture;
    if (int rc = hal_unlink(pin.c_str()); rc < 0)
        fail(capture, rc, "cannot unlink pin '" + pin + "'");
}

bool component_exists(const std::string& name)
{
    attach();
    hal_comp_info c{};
    return hal_find_comp(name.c_str(), &c) == 0;
}

bool component_is_ready(const std::string& name)
{
    attach();
    hal_comp_info c{};
    return hal_find_comp(name.c_str(), &c) == 0 && c.is_ready;
}

bool pin_has_writer(const std::string& name)
{
    attach();
    hal_pin_info pin{};
    if (hal_find_pin(name.c_str(), &pin) != 0)
        throw HalError("pin '" + name + "' does not exist");
    if (!pin.signal[0])
        return false;
    hal_sig_info sig{};
    return hal_find_sig(pin.signal, &sig) == 0 && sig.writers > 0;
}

// A pin's or a parameter's dict: the same keys for both (they differ only in their dir type).
template <class Info, class Query>
pyb::list info_dicts(Query query)
{
    pyb::list out;
    for (const Info& p : all_of<Info>(query)) {
        pyb::dict d;
        d["NAME"] = p.name;
        d["VALUE"] = from_hal(p.type, p.value);
        d["TYPE"] = static_cast<int>(p.type);
        d["DIRECTION"] = static_cast<int>(p.dir);
        out.append(d);
    }
    return out;
}

pyb::list get_info_pins()
{
    return info_dicts<hal_pin_info>(hal_query_pins);
}

pyb::list get_info_signals()
{
    std::vector<hal_pin_info> pins = all_of<hal_pin_info>(hal_query_pins);
    pyb::list out;
    for (const hal_sig_info& s : all_of<hal_sig_info>(hal_query_sigs)) {
        pyb::dict d;
        d["NAME"] = s.name;
        d["VALUE"] = from_hal(s.type, s.value);
        d["TYPE"] = static_cast<int>(s.type);
        pyb::object driver = pyb::none();
        for (const hal_pin_info& p : pins)
            if (p.dir == HAL_OUT && std::string_view(p.signal) == s.name)
                driver = pyb::str(p.name);
        d["DRIVER"] = driver;
        out.append(d);
    }
    return out;
}

pyb::list get_info_params()
{
    return info_dicts<hal_param_info>(hal_query_params);
}

void set_msg_level(int level)
{
    if (rtapi_set_msg_level(level) < 0)
        throw pyb::value_error("message level " + std::to_string(level) +
                               " is outside MSG_NONE (0) .. MSG_ALL (5)");
}

}  // namespace

void register_functions(pyb::module_& m)
{
    m.def("get_value", &get_value, pyb::arg("name"), "value of a pin, parameter or signal");
    m.def("set_p", &set_p, pyb::arg("name"), pyb::arg("value"),
          "set a pin or parameter as 'halcmd setp' does (value: a string or a number)");
    m.def("set_s", &set_s, pyb::arg("name"), pyb::arg("value"),
          "set a signal as 'halcmd sets' does (value: a string or a number)");
    m.def("new_sig", &new_sig, pyb::arg("name"), pyb::arg("type"), "create a signal");
    m.def("connect", &connect, pyb::arg("pin"), pyb::arg("signal"), "link a pin to a signal");
    m.def("disconnect", &disconnect, pyb::arg("pin"), "unlink a pin from its signal");
    m.def("component_exists", &component_exists, pyb::arg("name"));
    m.def("component_is_ready", &component_is_ready, pyb::arg("name"));
    m.def("pin_has_writer", &pin_has_writer, pyb::arg("name"),
          "True when the pin is linked to a signal that an output pin writes");
    m.def("get_info_pins", &get_info_pins, "list of dicts: NAME, VALUE, TYPE, DIRECTION");
    m.def("get_info_signals", &get_info_signals, "list of dicts: NAME, VALUE, TYPE, DRIVER (None if none)");
    m.def("get_info_params", &get_info_params, "list of dicts: NAME, VALUE, TYPE, DIRECTION");
    m.def("set_msg_level", &set_msg_level, pyb::arg("level"), "this process's RTAPI message level");
    m.def("get_msg_level", &rtapi_get_msg_level);
}

}  // namespace hal::py
