// SPDX-License-Identifier: GPL-2.0-or-later
// ini_values.cpp - lookups and the typed conversions of the EMC readers
// (ini-and-launch.md 1.1 "Typed conversions"), with FILE:LINE in every error.
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "ini/ini_file.hpp"

namespace hal::ini {

namespace {

// C's scanf reads a number and ignores what follows, so "1.5 (mm)" is 1.5 to the EMC
// readers. We keep that for text after a blank (notes users write after values) but
// refuse a number glued to other text ("1.5mm", "12abc"), which is more likely a typo.
bool rest_is_note(const char* end)
{
    return *end == '\0' || *end == ' ' || *end == '\t';
}

std::string upper(std::string_view s)
{
    std::string u(s);
    for (char& c : u)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return u;
}

enum class Conv { ok, bad, range };

Conv to_long(const std::string& text, long& out)
{
    if (text.empty())
        return Conv::bad;
    char* end = nullptr;
    errno = 0;
    long v = std::strtol(text.c_str(), &end, 0);   // %i: 0x hex, 0 octal
    if (end == text.c_str() || !rest_is_note(end))
        return Conv::bad;
    if (errno == ERANGE)
        return Conv::range;
    out = v;
    return Conv::ok;
}

}  // namespace

const IniFile::Entry* IniFile::lookup(std::string_view section, std::string_view key, int nth) const
{
    if (nth < 1)
        return nullptr;
    for (const Entry& e : entries_) {
        if (e.reachable && e.section == section && e.key == key && --nth == 0)
            return &e;
    }
    return nullptr;
}

std::optional<std::string> IniFile::find(std::string_view section, std::string_view key, int nth) const
{
    const Entry* e = lookup(section, key, nth);
    if (!e)
        return std::nullopt;
    return e->value;
}

std::vector<std::string> IniFile::find_all(std::string_view section, std::string_view key) const
{
    std::vector<std::string> out;
    for (const Entry& e : entries_)
        if (e.reachable && e.section == section && e.key == key)
            out.push_back(e.value);
    return out;
}

std::string IniFile::where(std::string_view section, std::string_view key, int nth) const
{
    const Entry* e = lookup(section, key, nth);
    if (!e)
        return path_;
    return e->file + ":" + std::to_string(e->line);
}

static Error bad_value(const IniFile::Entry& e, const char* what)
{
    return Error{-22, e.file + ":" + std::to_string(e.line) + ": [" + e.section + "]" + e.key + ": '" + e.value +
                          "' " + what};
}

Result<double> IniFile::get_double(std::string_view section, std::string_view key, double fallback) const
{
    const Entry* e = lookup(section, key, 1);
    if (!e)
        return fallback;
    const char* text = e->value.c_str();
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(text, &end);
    if (e->value.empty() || end == text || !rest_is_note(end) || !std::isfinite(v))
        return bad_value(*e, "is not a number");
    if (errno == ERANGE && std::fabs(v) > 1.0)
        return bad_value(*e, "is out of range");
    return v;
}

Result<long> IniFile::get_int(std::string_view section, std::string_view key, long fallback) const
{
    const Entry* e = lookup(section, key, 1);
    if (!e)
        return fallback;
    long v = 0;
    switch (to_long(e->value, v)) {
    case Conv::ok:
        return v;
    case Conv::range:
        return bad_value(*e, "is out of range");
    case Conv::bad:
        break;
    }
    return bad_value(*e, "is not an integer");
}

Result<bool> IniFile::get_bool(std::string_view section, std::string_view key, bool fallback) const
{
    const Entry* e = lookup(section, key, 1);
    if (!e)
        return fallback;
    long n = 0;
    if (to_long(e->value, n) == Conv::ok)   // the EMC readers try an integer first
        return n != 0;
    std::string u = upper(e->value);
    if (u == "TRUE" || u == "YES" || u == "ON")
        return true;
    if (u == "FALSE" || u == "NO" || u == "OFF")
        return false;
    return bad_value(*e, "is not a boolean (YES/NO, TRUE/FALSE, ON/OFF, 1/0)");
}

}  // namespace hal::ini
