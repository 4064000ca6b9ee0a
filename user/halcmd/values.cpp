// SPDX-License-Identifier: GPL-2.0-or-later
// values.cpp - see values.hpp.
#include "values.hpp"

#include <fnmatch.h>

#include <cctype>
#include <cmath>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace hal::halcmd {

const char* type_name(hal_type_t type)
{
    switch (type) {
    case HAL_BIT: return "bit";
    case HAL_S32: return "s32";
    case HAL_U32: return "u32";
    case HAL_S64: return "s64";
    case HAL_U64: return "u64";
    case HAL_FLOAT: return "float";
    default: return "unknown";
    }
}

std::optional<hal_type_t> parse_type_name(std::string_view name)
{
    if (name == "bit")
        return HAL_BIT;
    if (name == "s32")
        return HAL_S32;
    if (name == "u32")
        return HAL_U32;
    if (name == "float")
        return HAL_FLOAT;
    if (name == "s64")
        return HAL_S64;
    if (name == "u64")
        return HAL_U64;
    return std::nullopt;
}

const char* pin_dir_name(hal_pin_dir_t dir)
{
    switch (dir) {
    case HAL_IN: return "IN";
    case HAL_OUT: return "OUT";
    case HAL_IO: return "I/O";
    default: return "?";
    }
}

const char* param_dir_name(hal_param_dir_t dir)
{
    return dir == HAL_RW ? "RW" : "RO";
}

namespace {

Error bad_value(std::string_view text, const char* type, const char* accepted)
{
    std::string msg = "'";   // appended piecewise: "'" + std::string trips GCC 12's -Wrestrict at -O3
    msg += text;
    msg += "' is not a valid ";
    msg += type;
    msg += " value (";
    msg += accepted;
    msg += ")";
    return Error{-22, std::move(msg)};
}

// Optional sign, then decimal digits or 0x + hex digits; the whole text must match.
// Decimal is deliberate: strtol base 0 would read "010" as octal 8.
std::optional<long long> parse_integer(std::string_view text, bool allow_minus)
{
    std::string s(text);
    size_t i = 0;
    bool neg = false;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) {
        neg = s[i] == '-';
        if (neg && !allow_minus)
            return std::nullopt;
        i++;
    }
    int base = 10;
    if (i + 1 < s.size() && s[i] == '0' && (s[i + 1] == 'x' || s[i + 1] == 'X')) {
        base = 16;
        i += 2;
    }
    if (i >= s.size())
        return std::nullopt;
    for (size_t k = i; k < s.size(); k++) {
        bool ok = base == 16 ? std::isxdigit(static_cast<unsigned char>(s[k]))
                             : std::isdigit(static_cast<unsigned char>(s[k]));
        if (!ok)
            return std::nullopt;
    }
    if (s.size() - i > 18)
        return std::nullopt;             // far outside 32 bits anyway; avoid overflow
    long long v = std::strtoll(s.c_str() + i, nullptr, base);
    return neg ? -v : v;
}

// The same rules for 64-bit values: the magnitude as unsigned, with its sign.
std::optional<std::pair<bool, unsigned long long>> parse_integer64(std::string_view text)
{
    std::string s(text);
    size_t i = 0;
    bool neg = false;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) {
        neg = s[i] == '-';
        i++;
    }
    int base = 10;
    if (i + 1 < s.size() && s[i] == '0' && (s[i + 1] == 'x' || s[i + 1] == 'X')) {
        base = 16;
        i += 2;
    }
    if (i >= s.size())
        return std::nullopt;
    for (size_t k = i; k < s.size(); k++) {
        bool ok = base == 16 ? std::isxdigit(static_cast<unsigned char>(s[k]))
                             : std::isdigit(static_cast<unsigned char>(s[k]));
        if (!ok)
            return std::nullopt;
    }
    errno = 0;
    unsigned long long v = std::strtoull(s.c_str() + i, nullptr, base);
    if (errno == ERANGE)
        return std::nullopt;
    return std::make_pair(neg, v);
}

}  // namespace

// RULINGS.md "bit values": what LinuxCNC's halcmd accepts for bits.
std::optional<bool> parse_bit(std::string_view text)
{
    std::string t;
    for (char c : text)
        t += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (t == "1" || t == "true" || t == "on" || t == "yes")
        return true;
    if (t == "0" || t == "false" || t == "off" || t == "no")
        return false;
    return std::nullopt;
}

Result<hal_value> parse_value(hal_type_t type, std::string_view text)
{
    hal_value v{};
    switch (type) {
    case HAL_BIT:
        if (auto b = parse_bit(text)) {
            v.b = *b;
            return v;
        }
        return bad_value(text, "bit", "use 1/0, true/false, on/off or yes/no, in any case");
    case HAL_S32: {
        auto n = parse_integer(text, true);
        if (!n || *n < INT32_MIN || *n > INT32_MAX)
            return bad_value(text, "s32",
                             "use a decimal or 0x hex integer from -2147483648 to 2147483647");
        v.s = static_cast<__s32>(*n);
        return v;
    }
    case HAL_U32: {
        auto n = parse_integer(text, false);
        if (!n || *n < 0 || *n > UINT32_MAX)
            return bad_value(text, "u32", "use a decimal or 0x hex integer from 0 to 4294967295");
        v.u = static_cast<__u32>(*n);
        return v;
    }
    case HAL_S64: {
        auto n = parse_integer64(text);
        bool fits = n && (n->first ? n->second <= 9223372036854775808ULL : n->second <= 9223372036854775807ULL);
        if (!fits)
            return bad_value(text, "s64", "use a decimal or 0x hex integer from -9223372036854775808 to "
                                          "9223372036854775807");
        v.ls = n->first ? static_cast<long long>(0ULL - n->second) : static_cast<long long>(n->second);
        return v;
    }
    case HAL_U64: {
        auto n = parse_integer64(text);
        if (!n || (n->first && n->second != 0))
            return bad_value(text, "u64", "use a decimal or 0x hex integer from 0 to 18446744073709551615");
        v.lu = n->second;
        return v;
    }
    case HAL_FLOAT: {
        std::string s(text);
        char* end = nullptr;
        errno = 0;
        double d = std::strtod(s.c_str(), &end);
        // Finite values only (issue 19, item 9): nan and inf would spread through every
        // component downstream, and 1e999 would become inf. A value too small to
        // represent (1e-999) reads as the nearest double, as strtod rounds it.
        bool overflow = errno == ERANGE && std::isinf(d);
        if (s.empty() || std::isspace(static_cast<unsigned char>(s[0])) || end != s.c_str() + s.size() ||
            overflow || !std::isfinite(d))
            return bad_value(text, "float",
                             "use a finite number such as 2, -0.5, 1e-3 or 0x1p4; nan, inf and "
                             "values beyond +-1.7976931348623157e308 are refused");
        v.f = d;
        return v;
    }
    default:
        return Error{-22, "unknown HAL type"};
    }
}

std::string format_float(double v)
{
    char buf[40];
    for (int prec = 6; prec <= 17; prec++) {
        std::snprintf(buf, sizeof(buf), "%.*g", prec, v);
        if (std::strtod(buf, nullptr) == v)
            break;                       // also stops at nan (never equal) after %.17g
    }
    return buf;
}

std::string format_value(hal_type_t type, const hal_value& v)
{
    switch (type) {
    case HAL_BIT: return v.b ? "TRUE" : "FALSE";
    case HAL_S32: return std::to_string(v.s);
    case HAL_U32: return std::to_string(v.u);
    case HAL_S64: return std::to_string(v.ls);
    case HAL_U64: return std::to_string(v.lu);
    case HAL_FLOAT: return format_float(v.f);
    default: return "?";
    }
}

bool name_matches(const std::vector<std::string>& patterns, std::string_view name)
{
    if (patterns.empty())
        return true;
    std::string n(name);
    for (const std::string& p : patterns) {
        if (n.compare(0, p.size(), p) == 0)
            return true;
        if (fnmatch(p.c_str(), n.c_str(), 0) == 0)
            return true;
    }
    return false;
}

}  // namespace hal::halcmd
