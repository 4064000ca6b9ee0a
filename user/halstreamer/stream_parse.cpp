// SPDX-License-Identifier: GPL-2.0-or-later
// stream_parse.cpp - parse halstreamer's options and input lines.
#include "stream_parse.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "fifo_attach.hpp"

namespace hal {

namespace {

bool is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

std::vector<std::string_view> split_fields(std::string_view line)
{
    std::vector<std::string_view> fields;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_space(line[i]))
            i++;
        size_t start = i;
        while (i < line.size() && !is_space(line[i]))
            i++;
        if (i > start)
            fields.emplace_back(line.substr(start, i - start));
    }
    return fields;
}

const char* type_name(hal_fifo_type t)
{
    switch (t) {
    case HAL_FIFO_FLOAT: return "float";
    case HAL_FIFO_BIT: return "bit (0 or 1)";
    case HAL_FIFO_S32: return "s32";
    case HAL_FIFO_U32: return "u32";
    case HAL_FIFO_S64: return "s64";
    case HAL_FIFO_U64: return "u64";
    default: return "?";
    }
}

// The common spellings, with std::from_chars (issue 20): a plain decimal number that
// it takes whole and whose value strtod/strtoll would give too (a nonzero normal
// double, an integer in range). Anything else (+, hex, inf, nan, underflow, errors)
// is left to parse_value(), so what is accepted, and how, stays strtod's.
bool parse_fast(hal_fifo_type t, std::string_view f, hal_fifo_value& v)
{
    const char* b = f.data();
    const char* e = b + f.size();
    if (f.empty() || !(f[0] == '-' || (f[0] >= '0' && f[0] <= '9')))
        return false;
    switch (t) {
    case HAL_FIFO_FLOAT: {
        double d;
        auto r = std::from_chars(b, e, d, std::chars_format::fixed | std::chars_format::scientific);
        if (r.ec != std::errc() || r.ptr != e || std::fpclassify(d) != FP_NORMAL)
            return false;
        v.f = d;
        return true;
    }
    case HAL_FIFO_S32:
    case HAL_FIFO_S64: {
        long long s;
        auto r = std::from_chars(b, e, s);
        if (r.ec != std::errc() || r.ptr != e || (t == HAL_FIFO_S32 && (s < INT32_MIN || s > INT32_MAX)))
            return false;
        v.s = s;
        return true;
    }
    case HAL_FIFO_U32:
    case HAL_FIFO_U64: {
        unsigned long long u;
        auto r = std::from_chars(b, e, u);
        if (r.ec != std::errc() || r.ptr != e || (t == HAL_FIFO_U32 && u > UINT32_MAX))
            return false;
        v.u = u;
        return true;
    }
    default:
        return false;
    }
}

// One field as type t, or false.
bool parse_value(hal_fifo_type t, const std::string& field, hal_fifo_value& v)
{
    char* end = nullptr;
    errno = 0;
    switch (t) {
    case HAL_FIFO_FLOAT:
        v.f = std::strtod(field.c_str(), &end);
        return *end == 0 && errno != ERANGE;
    case HAL_FIFO_BIT:
        if (field != "0" && field != "1")
            return false;
        v.u = field == "1" ? 1 : 0;
        return true;
    case HAL_FIFO_S32: {
        long long s = std::strtoll(field.c_str(), &end, 10);
        if (*end || errno || s < INT32_MIN || s > INT32_MAX)
            return false;
        v.s = s;
        return true;
    }
    case HAL_FIFO_U32: {
        if (field[0] == '-')
            return false;  // strtoul would wrap it around
        unsigned long long u = std::strtoull(field.c_str(), &end, 10);
        if (*end || errno || u > UINT32_MAX)
            return false;
        v.u = u;
        return true;
    }
    case HAL_FIFO_S64: {
        long long s = std::strtoll(field.c_str(), &end, 10);
        if (*end || errno || field.empty())
            return false;
        v.s = s;
        return true;
    }
    case HAL_FIFO_U64: {
        if (field[0] == '-')
            return false;
        unsigned long long u = std::strtoull(field.c_str(), &end, 10);
        if (*end || errno || field.empty())
            return false;
        v.u = u;
        return true;
    }
    default:
        return false;
    }
}

}  // namespace

Result<StreamerOptions> parse_streamer_options(std::span<char* const> args)
{
    StreamerOptions opt;
    bool have_file = false;
    bool options_done = false;

    for (size_t i = 1; i < args.size(); i++) {
        std::string_view a = args[i];
        if (options_done || a.size() < 2 || a[0] != '-') {
            if (have_file)
                return Error{-EINVAL, "more than one FILENAME given ('" + opt.filename + "', '" +
                                          std::string(a) + "')"};
            opt.filename = std::string(a);
            have_file = true;
        } else if (a == "--") {
            options_done = true;
        } else if (a == "-h") {
            opt.help = true;
        } else if (a.substr(0, 2) == "-c") {
            std::string_view value = a.substr(2);
            if (value.empty()) {
                if (i + 1 >= args.size())
                    return Error{-EINVAL, "option -c needs a value"};
                value = args[++i];
            }
            auto v = parse_number(value, 0, HAL_FIFO_MAX_FIFOS - 1);
            if (!v)
                return Error{-EINVAL, "-c " + std::string(value) +
                                          ": CHAN must be a FIFO number 0.." +
                                          std::to_string(HAL_FIFO_MAX_FIFOS - 1)};
            opt.channel = static_cast<int>(*v);
        } else {
            return Error{-EINVAL, "unknown option " + std::string(a)};
        }
    }
    return opt;
}

bool is_blank_line(std::string_view line)
{
    for (char c : line)
        if (!is_space(c))
            return false;
    return true;
}

Result<std::vector<hal_fifo_value>> parse_stream_line(std::string_view cfg, std::string_view line)
{
    std::vector<std::string_view> fields = split_fields(line);
    // LinuxCNC's halstreamer reads the fields it needs and ignores the rest (a trailing
    // "# comment", extra columns); too few is an error.
    if (fields.size() < cfg.size())
        return Error{-EINVAL, "expected " + std::to_string(cfg.size()) + " values (cfg '" +
                                  std::string(cfg) + "'), found " + std::to_string(fields.size())};
    std::vector<hal_fifo_value> values(cfg.size());
    for (size_t m = 0; m < cfg.size(); m++) {
        hal_fifo_type t = hal_fifo_type_of(cfg[m]);
        if (parse_fast(t, fields[m], values[m]))
            continue;
        std::string field(fields[m]);
        if (!parse_value(t, field, values[m]))
            return Error{-EINVAL, "value " + std::to_string(m + 1) + " '" + field +
                                      "' is not a valid " + type_name(t)};
    }
    return values;
}

}  // namespace hal
