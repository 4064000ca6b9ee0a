// SPDX-License-Identifier: GPL-2.0-or-later
// cmd_value.cpp - setp, getp, ptype, sets, gets, stype (halcmd(1)). When a parameter
// and a pin share a name, the parameter is acted on, as the page says.
#include <cerrno>
#include <cstdio>

#include "commands.hpp"
#include "hal_query.h"
#include "session.hpp"
#include "values.hpp"

namespace hal::halcmd {

namespace {

struct Object {
    bool is_param = false;
    hal_type_t type = HAL_TYPE_UNSPECIFIED;
    hal_value value{};
};

Result<Object> find_param_or_pin(const std::string& cmd, const std::string& name)
{
    Object o;
    hal_param_info pa;
    hal_pin_info pi;
    if (hal_find_param(name.c_str(), &pa) == 0) {
        o.is_param = true;
        o.type = pa.type;
        o.value = pa.value;
    } else if (hal_find_pin(name.c_str(), &pi) == 0) {
        o.type = pi.type;
        o.value = pi.value;
    } else {
        return Error{-ENOENT, cmd + ": no parameter or pin named '" + name + "'"};
    }
    return o;
}

Result<hal_sig_info> find_signal(const std::string& cmd, const std::string& name)
{
    hal_sig_info si;
    if (hal_find_sig(name.c_str(), &si) != 0)
        return Error{-ENOENT, cmd + ": no signal named '" + name + "'"};
    return si;
}

}  // namespace

Result<void> cmd_setp(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_PARAMS, "setp"); !r)
        return r;
    auto o = find_param_or_pin("setp", args[0]);
    if (!o)
        return o.error();
    const char* kind = o->is_param ? "parameter" : "pin";
    auto v = parse_value(o->type, args[1]);
    if (!v)
        return Error{-EINVAL, "setp: " + std::string(kind) + " '" + args[0] + "': " + v.error().message};
    int rc = o->is_param ? hal_set_param_value(args[0].c_str(), &*v) : hal_set_pin_value(args[0].c_str(), &*v);
    if (auto r = s.check(rc, "setp: setting " + std::string(kind) + " '" + args[0] + "'"); !r)
        return r;
    s.info(std::string(o->is_param ? "Parameter" : "Pin") + " '" + args[0] + "' set to " + format_value(o->type, *v));
    return ok();
}

Result<void> cmd_getp(Session&, Args args)
{
    auto o = find_param_or_pin("getp", args[0]);
    if (!o)
        return o.error();
    std::printf("%s\n", format_value(o->type, o->value).c_str());
    return ok();
}

Result<void> cmd_ptype(Session&, Args args)
{
    auto o = find_param_or_pin("ptype", args[0]);
    if (!o)
        return o.error();
    std::printf("%s\n", type_name(o->type));
    return ok();
}

Result<void> cmd_sets(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_PARAMS, "sets"); !r)
        return r;
    auto si = find_signal("sets", args[0]);
    if (!si)
        return si.error();
    auto v = parse_value(si->type, args[1]);
    if (!v)
        return Error{-EINVAL, "sets: signal '" + args[0] + "': " + v.error().message};
    if (auto r = s.check(hal_set_sig_value(args[0].c_str(), &*v), "sets: setting signal '" + args[0] + "'"); !r)
        return r;
    s.info("Signal '" + args[0] + "' set to " + format_value(si->type, *v));
    return ok();
}

Result<void> cmd_gets(Session&, Args args)
{
    auto si = find_signal("gets", args[0]);
    if (!si)
        return si.error();
    std::printf("%s\n", format_value(si->type, si->value).c_str());
    return ok();
}

Result<void> cmd_stype(Session&, Args args)
{
    auto si = find_signal("stype", args[0]);
    if (!si)
        return si.error();
    std::printf("%s\n", type_name(si->type));
    return ok();
}

}  // namespace hal::halcmd
