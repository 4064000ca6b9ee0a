// SPDX-License-Identifier: GPL-2.0-or-later
// stream_parse.cpp - parse halstreamer's options and input lines.
#include "stream_parse.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdlib>

#include "fifo_attach.hpp"

namespace hal {

namespace {

bool is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

std::vector<std::string> split_fields(std::string_view line)
{
    std::vector<std::string> fields;
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
    std::vector<std::string> fields = split_fields(line);
    // LinuxCNC's halstreamer reads the fields it needs and ignores the rest (a trailing
    // "# comment", extra columns); too few is an error.
    if (fields.size() < cfg.size())
        return Error{-EINVAL, "expected " + std::to_string(cfg.size()) + " values (cfg '" +
                                  std::string(cfg) + "'), found " + std::to_string(fields.size())};
    std::vector<hal_fifo_value> values(cfg.size());
    for (size_t m = 0; m < cfg.size(); m++) {
        hal_fifo_type t = hal_fifo_type_of(cfg[m]);
        if (!parse_value(t, fields[m], values[m]))
            return Error{-EINVAL, "value " + std::to_string(m + 1) + " '" + fields[m] +
                                      "' is not a valid " + type_name(t)};
    }
    return values;
}

}  // namespace hal
