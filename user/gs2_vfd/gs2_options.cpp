// SPDX-License-Identifier: GPL-2.0-or-later
// gs2_options.cpp - parse_gs2_options(): gs2_vfd(1)'s OPTIONS section.
#include "gs2_options.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <string_view>

namespace hal::gs2 {

namespace {

constexpr std::array<int, 11> valid_rates = {110, 300, 600, 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200};

struct Spec {
    char short_name;
    const char* long_name;
    bool has_value;
};

constexpr std::array<Spec, 10> specs = {{{'b', "bits", true},     {'d', "device", true}, {'g', "debug", false},
                                         {'n', "name", true},     {'p', "parity", true}, {'r', "rate", true},
                                         {'s', "stopbits", true}, {'t', "target", true}, {'v', "verbose", false},
                                         {'h', "help", false}}};

const Spec* find_spec(std::string_view a)
{
    if (a.size() < 2 || a[0] != '-')
        return nullptr;
    std::string_view body = a.substr(a[1] == '-' ? 2 : 1);
    for (const Spec& s : specs)
        if ((body.size() == 1 && body[0] == s.short_name) || body == s.long_name)
            return &s;
    return nullptr;
}

Result<int> number(std::string_view opt, std::string_view text)
{
    int v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size())
        return Error{-22, std::string(opt) + ": '" + std::string(text) + "' is not a number"};
    return v;
}

}  // namespace

Result<Gs2Options> parse_gs2_options(std::span<char* const> args)
{
    Gs2Options o;
    for (size_t i = 1; i < args.size(); i++) {
        std::string_view a = args[i];
        const Spec* s = find_spec(a);
        if (!s)
            return Error{-22, "unknown option '" + std::string(a) + "'"};
        std::string opt = std::string("-") + s->long_name;
        std::string_view val;
        if (s->has_value) {
            if (i + 1 >= args.size())
                return Error{-22, opt + " needs a value"};
            val = args[++i];
        }
        switch (s->short_name) {
        case 'b': {
            auto v = number(opt, val);
            if (!v)
                return v.error();
            if (*v < 5 || *v > 8)
                return Error{-22, "-bits: " + std::string(val) + " data bits; must be 5 to 8"};
            o.bits = *v;
            break;
        }
        case 'd': o.device = std::string(val); break;
        case 'g': o.debug = o.verbose = true; break;
        case 'n':
            if (val.empty())
                return Error{-22, "-name: the name is empty"};
            o.name = std::string(val);
            break;
        case 'p':
            if (val == "even")
                o.parity = 'E';
            else if (val == "odd")
                o.parity = 'O';
            else if (val == "none")
                o.parity = 'N';
            else
                return Error{-22, "-parity: '" + std::string(val) + "'; use even, odd or none"};
            break;
        case 'r': {
            auto v = number(opt, val);
            if (!v)
                return v.error();
            if (std::find(valid_rates.begin(), valid_rates.end(), *v) == valid_rates.end())
                return Error{-22, "-rate: " + std::string(val) +
                                      " baud is not one of 110, 300, 600, 1200, 2400, 4800, 9600, "
                                      "19200, 38400, 57600, 115200"};
            o.rate = *v;
            break;
        }
        case 's': {
            auto v = number(opt, val);
            if (!v)
                return v.error();
            if (*v != 1 && *v != 2)
                return Error{-22, "-stopbits: " + std::string(val) + "; must be 1 or 2"};
            o.stopbits = *v;
            break;
        }
        case 't': {
            auto v = number(opt, val);
            if (!v)
                return v.error();
            if (*v < 1 || *v > 247)
                return Error{-22, "-target: " + std::string(val) + "; a Modbus target is 1 to 247"};
            o.target = *v;
            break;
        }
        case 'v': o.verbose = true; break;
        case 'h': o.help = true; break;
        }
    }
    return o;
}

}  // namespace hal::gs2
