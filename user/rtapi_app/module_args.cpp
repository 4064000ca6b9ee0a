// SPDX-License-Identifier: GPL-2.0-or-later
// module_args.cpp - parsing, checking and joining insmod-style module arguments.
#include "module_args.hpp"

#include <algorithm>
#include <cerrno>

namespace hal {
namespace {

Error arg_error(std::string_view module, const std::string& what)
{
    return Error{-EINVAL, std::string(module) + ": " + what};
}

// Module parameters are C variables, so a name that is no C identifier can never
// be declared: report it like any other unknown name.
bool is_identifier(std::string_view s)
{
    if (s.empty() || (s[0] >= '0' && s[0] <= '9'))
        return false;
    return std::all_of(s.begin(), s.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_';
    });
}

// Check one split item and add it, the last value of a repeated name winning.
Result<void> add_arg(std::string_view module, std::vector<ModuleArg>& out, std::string name,
                     std::string value, bool has_equals, std::string_view shown)
{
    if (!has_equals) {
        if (name.empty())
            return arg_error(module, "empty argument");
        return arg_error(module, "parameter '" + name + "' has no value (use " + name +
                                     "=VALUE)");
    }
    if (name.empty())
        return arg_error(module, "argument '" + std::string(shown) + "' has no parameter name");
    if (!is_identifier(name))
        return arg_error(module, "unknown parameter '" + name + "'");
    auto same = std::find_if(out.begin(), out.end(),
                             [&](const ModuleArg& a) { return a.name == name; });
    if (same != out.end())
        same->value = std::move(value);
    else
        out.push_back(ModuleArg{std::move(name), std::move(value)});
    return {};
}

bool is_quote(char c) { return c == '"' || c == '\''; }

}  // namespace

bool is_module_name(std::string_view name)
{
    constexpr size_t max_len = 31;  // RTAPI_NAME_LEN; this file stays free of rtapi.h
    if (name.empty() || name.size() > max_len)
        return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
}

Result<std::vector<ModuleArg>> parse_module_args(std::string_view module,
                                                 const std::vector<std::string>& items)
{
    std::vector<ModuleArg> out;
    for (const std::string& item : items) {
        auto eq = item.find('=');
        bool has_equals = eq != std::string::npos;
        std::string name = item.substr(0, eq);
        std::string value = has_equals ? item.substr(eq + 1) : std::string();
        // insmod strips one pair of quotes around a value.
        if (value.size() >= 2 && is_quote(value.front()) && value.back() == value.front())
            value = value.substr(1, value.size() - 2);
        auto r = add_arg(module, out, std::move(name), std::move(value), has_equals, item);
        if (!r)
            return r.error();
    }
    return out;
}

Result<std::vector<ModuleArg>> parse_module_args(std::string_view module, std::string_view joined)
{
    std::vector<ModuleArg> out;
    size_t i = 0;
    while (i < joined.size()) {
        if (joined[i] == ' ' || joined[i] == '\t') {
            ++i;
            continue;
        }
        // One item: up to the next blank outside quotes. Quote characters are
        // removed; the first '=', quoted or not, separates the name (as the
        // kernel's parser does, so "count=3" in quotes still works).
        size_t start = i;
        char quote = 0;
        bool has_equals = false;
        std::string name, value;
        for (; i < joined.size(); ++i) {
            char c = joined[i];
            if (quote && c == quote) {
                quote = 0;
            } else if (!quote && (c == ' ' || c == '\t')) {
                break;
            } else if (!quote && is_quote(c)) {
                quote = c;
            } else if (c == '=' && !has_equals) {
                has_equals = true;
            } else {
                (has_equals ? value : name) += c;
            }
        }
        std::string_view shown = joined.substr(start, i - start);
        if (quote)
            return arg_error(module, "unterminated quote in '" + std::string(shown) + "'");
        auto r = add_arg(module, out, std::move(name), std::move(value), has_equals, shown);
        if (!r)
            return r.error();
    }
    return out;
}

Result<void> check_module_args(std::string_view module, const std::vector<ModuleArg>& args,
                               const std::vector<std::string>& declared)
{
    for (const ModuleArg& a : args) {
        if (std::find(declared.begin(), declared.end(), a.name) == declared.end())
            return arg_error(module, "unknown parameter '" + a.name + "'");
    }
    return {};
}

Result<std::string> join_module_args(std::string_view module, const std::vector<ModuleArg>& args)
{
    std::string out;
    for (const ModuleArg& a : args) {
        const std::string& v = a.value;
        if (v.find_first_of(std::string_view("\n\r\0", 3)) != std::string::npos)
            return arg_error(module, "value of parameter '" + a.name +
                                         "' contains a line break or NUL");
        bool has_dq = v.find('"') != std::string::npos;
        bool has_sq = v.find('\'') != std::string::npos;
        if (has_dq && has_sq)
            return arg_error(module, "value of parameter '" + a.name +
                                         "' contains both kinds of quote");
        if (!out.empty())
            out += ' ';
        out += a.name;
        out += '=';
        if (has_dq)
            out += '\'' + v + '\'';
        else if (has_sq || v.find_first_of(" \t") != std::string::npos)
            out += '"' + v + '"';
        else
            out += v;
    }
    return out;
}

}  // namespace hal
