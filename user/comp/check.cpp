// SPDX-License-Identifier: GPL-2.0-or-later
// check.cpp - see check.hpp.
#include "check.hpp"

#include <map>
#include <set>

#include "names.hpp"

namespace hal::comp {

namespace {

const std::set<std::string> known_options = {
    "singleton", "default_count", "count_function", "rtapi_app", "data", "extra_setup",
    "extra_cleanup", "userspace", "userinit", "constructable", "personality",
    "extra_compile_args", "extra_link_args"};

// Names the generated C uses itself in the user's code region: a pin or variable so
// called would become a macro there and break FUNCTION(), EXTRA_SETUP() or the like.
std::set<std::string> reserved_c_names(const Component& c)
{
    std::set<std::string> r = {"period", "fperiod", "personality", "comp_id", "FUNCTION"};
    if (c.find_option("data"))
        r.insert("data");
    if (c.option_on("extra_setup"))
        r.insert({"prefix", "extra_arg"});
    if (c.is_userspace())
        r.insert({"argc", "argv"});
    return r;
}

Error at(const Component& c, int line, const std::string& message)
{
    return Error{-1, c.file + ":" + std::to_string(line) + ": " + message};
}

}  // namespace

Result<void> check_component(const Component& c, std::string* warnings)
{
    auto warn = [&](int line, const std::string& m) {
        if (warnings)
            *warnings += c.file + ":" + std::to_string(line) + ": warning: " + m + "\n";
    };
    const std::set<std::string> reserved = reserved_c_names(c);
    std::map<std::string, int> c_names;  // C name -> line of its declaration
    std::set<std::string> hal_names;
    for (const Item& it : c.items) {
        const char* kind = it.is_pin ? "pin" : "param";
        int blocks = hash_blocks(it.name);
        if (it.array_size && blocks == 0)
            return at(c, it.line, std::string(kind) + " '" + it.name +
                                      "' is an array but its name has no '#' for the index");
        if (blocks > 1)
            return at(c, it.line, std::string(kind) + " '" + it.name + "' has more than one block of '#'");
        if (!it.array_size && blocks)
            return at(c, it.line, std::string(kind) + " '" + it.name +
                                      "' has '#' in its name but no array size ([N])");
        std::string cn = to_c(it.name);
        if (cn.empty() || !(std::isalpha(static_cast<unsigned char>(cn[0])) || cn[0] == '_'))
            return at(c, it.line, std::string(kind) + " '" + it.name + "' does not make a C name");
        if (reserved.contains(cn))
            return at(c, it.line, std::string(kind) + " '" + it.name + "': the C name '" + cn +
                                      "' is reserved by the generated code; rename it (e.g. '" +
                                      it.name + "_')");
        if (auto f = c_names.find(cn); f != c_names.end())
            return at(c, it.line, std::string(kind) + " '" + it.name + "': C name '" + cn +
                                      "' already used on line " + std::to_string(f->second));
        c_names.emplace(cn, it.line);
        if (!hal_names.insert(to_hal(it.name)).second)
            return at(c, it.line, std::string(kind) + " '" + it.name + "': HAL name '" +
                                      to_hal(it.name) + "' declared twice");
        if ((it.condition.size() || it.array_count.size()) && !c.has_personality())
            warn(it.line, std::string(kind) + " '" + it.name +
                              "' depends on personality but 'option personality' is not set");
    }
    for (const Variable& v : c.variables) {
        if (reserved.contains(v.name))
            return at(c, v.line, "variable '" + v.name + "' is reserved by the generated code");
        if (auto f = c_names.find(v.name); f != c_names.end())
            return at(c, v.line, "variable '" + v.name + "' already declared on line " +
                                     std::to_string(f->second));
        c_names.emplace(v.name, v.line);
    }
    std::set<std::string> fnames;
    for (const Function& f : c.functions) {
        if (!fnames.insert(f.name).second)
            return at(c, f.line, "function '" + f.name + "' declared twice");
        if (f.name == "_" && c.functions.size() > 1)
            return at(c, f.line, "function '_' must be the only function of the component");
        if (c_names.contains(f.name))
            return at(c, f.line, "function '" + f.name + "' has the C name of a pin, param or variable");
    }
    std::set<std::string> onames;
    for (const Option& o : c.options) {
        if (!onames.insert(o.name).second)
            return at(c, o.line, "option '" + o.name + "' given twice");
        if (!known_options.contains(o.name))
            warn(o.line, "unknown option '" + o.name + "' ignored");
    }
    if (auto* o = c.find_option("default_count")) {
        char* end = nullptr;
        long n = std::strtol(o->value.c_str(), &end, 0);
        if (*end || n < 1 || n > 64)
            return at(c, o->line, "option default_count must be 1..64, not '" + o->value + "'");
    }
    for (const ModParam& m : c.modparams) {
        if (m.type != "dummy" &&
            (m.name == "count" || m.name == "names" || m.name == "personality" ||
             reserved.contains(m.name) || c_names.contains(m.name)))
            return at(c, m.line, "modparam '" + m.name + "' clashes with a name already in use");
    }
    if (c.is_userspace()) {
        if (!c.functions.empty())
            return at(c, c.functions.front().line,
                      "a userspace component has no functions: write user_mainloop() instead");
    } else if (c.functions.empty()) {
        return at(c, c.line, "realtime component '" + c.name +
                                 "' needs at least one 'function' declaration");
    }
    if (c.license.empty())
        warn(1, "no 'license' declaration: the kernel will refuse GPL-only symbols");
    return {};
}

const Option* Component::find_option(const std::string& name) const
{
    for (const Option& o : options)
        if (o.name == name)
            return &o;
    return nullptr;
}

bool Component::option_on(const std::string& name) const
{
    const Option* o = find_option(name);
    return o && o->value != "no" && o->value != "false" && o->value != "0" && o->value != "FALSE";
}

std::string Component::option_value(const std::string& name) const
{
    const Option* o = find_option(name);
    return o ? o->value : std::string();
}

const char* type_name(HalType t)
{
    switch (t) {
    case HalType::Bit: return "bit";
    case HalType::Float: return "float";
    case HalType::S32: return "s32";
    case HalType::U32: return "u32";
    case HalType::S64: return "s64";
    case HalType::U64: return "u64";
    }
    return "?";
}

const char* dir_name(Dir d)
{
    switch (d) {
    case Dir::In: return "in";
    case Dir::Out: return "out";
    case Dir::Io: return "io";
    case Dir::Ro: return "r";
    case Dir::Rw: return "rw";
    }
    return "?";
}

}  // namespace hal::comp
