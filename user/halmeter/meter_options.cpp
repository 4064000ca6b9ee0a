// SPDX-License-Identifier: GPL-2.0-or-later
// meter_options.cpp - parse_meter_options(): halmeter(1)'s options plus terminal mode.
#include "meter_options.hpp"

#include <charconv>
#include <string_view>

namespace hal::meter {

namespace {

Result<long> parse_number(std::string_view opt, std::string_view text, long min, long max)
{
    long v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || v < min || v > max)
        return Error{-22, std::string(opt) + " needs a number from " + std::to_string(min) + " to " +
                              std::to_string(max) + ", not '" + std::string(text) + "'"};
    return v;
}

bool is_number(std::string_view s)
{
    long v;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && end == s.data() + s.size();
}

}  // namespace

const char* kind_name(Kind k)
{
    switch (k) {
    case Kind::pin: return "pin";
    case Kind::sig: return "sig";
    case Kind::param: return "param";
    default: return "";
    }
}

Result<MeterOptions> parse_meter_options(std::span<char* const> args)
{
    MeterOptions o;
    bool gave_count = false;
    for (size_t i = 1; i < args.size(); i++) {
        std::string_view a = args[i];
        auto next = [&](std::string_view what) -> Result<std::string_view> {
            if (i + 1 >= args.size())
                return Error{-22, std::string(a) + " needs " + std::string(what)};
            return std::string_view(args[++i]);
        };
        if (a == "-h" || a == "--help") {
            o.help = true;
        } else if (a == "-s") {
            o.small = true;
        } else if (a == "-t") {
            o.terminal = true;
        } else if (a == "-l") {
            o.terminal = o.lines = true;
        } else if (a == "-i" || a == "-n") {
            auto t = next(a == "-i" ? "an interval in milliseconds" : "a count");
            if (!t)
                return t.error();
            auto v = a == "-i" ? parse_number(a, *t, 1, 3600000) : parse_number(a, *t, 1, 1000000000);
            if (!v)
                return v.error();
            if (a == "-i") {
                o.interval_ms = static_cast<int>(*v);
            } else {
                o.count = *v;
                gave_count = true;
            }
        } else if (a == "-g") {
            if (i + 2 >= args.size())
                return Error{-22, "-g needs X and Y positions (and optionally a width)"};
            auto x = parse_number("-g X", args[i + 1], -100000, 100000);
            auto y = parse_number("-g Y", args[i + 2], -100000, 100000);
            if (!x)
                return x.error();
            if (!y)
                return y.error();
            o.has_geometry = true;
            o.x = static_cast<int>(*x);
            o.y = static_cast<int>(*y);
            i += 2;
            if (i + 1 < args.size() && is_number(args[i + 1])) {
                auto w = parse_number("-g WIDTH", args[++i], 50, 100000);
                if (!w)
                    return w.error();
                o.width = static_cast<int>(*w);
            }
        } else if (a == "pin" || a == "sig" || a == "param") {
            if (o.item.kind != Kind::none)
                return Error{-22, "only one item can be shown; '" + std::string(a) + "' is a second one"};
            auto n = next("a name");
            if (!n)
                return n.error();
            o.item.kind = a == "pin" ? Kind::pin : a == "sig" ? Kind::sig : Kind::param;
            o.item.name = std::string(*n);
        } else {
            return Error{-22, "unexpected argument '" + std::string(a) + "' (expected pin, sig or param NAME)"};
        }
    }
    if (o.help)
        return o;
    if (o.small && o.item.kind == Kind::none)
        return Error{-22, "-s needs an item: pin, sig or param NAME"};
    if (o.terminal && o.item.kind == Kind::none)
        return Error{-22, "terminal mode needs an item: pin, sig or param NAME"};
    if (!o.terminal && gave_count)
        return Error{-22, "-n applies to terminal mode only (add -t)"};
    return o;
}

}  // namespace hal::meter
