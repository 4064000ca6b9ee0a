// SPDX-License-Identifier: GPL-2.0-or-later
// plot_options.cpp - see plot_options.hpp.
#include "plot_options.hpp"

#include <charconv>
#include <string_view>

namespace hal {

namespace {

bool number(std::string_view s, long long min, long long max, long long& out)
{
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size() && out >= min && out <= max;
}

bool ends_with(std::string_view s, std::string_view tail)
{
    return s.size() > tail.size() && s.substr(s.size() - tail.size()) == tail;
}

}  // namespace

Result<PlotOptions> parse_plot_options(std::span<char* const> args)
{
    PlotOptions o;
    for (size_t i = 1; i < args.size(); i++) {
        std::string_view a = args[i];
        if (a == "-h" || a == "--help") {
            o.help = true;
            continue;
        }
        if (a != "-c" && a != "-n" && a != "-o" && a != "-T" && a != "-s")
            return Error{-1, "unknown argument '" + std::string(a) + "'"};
        if (i + 1 >= args.size())
            return Error{-1, "option " + std::string(a) + " needs a value"};
        std::string_view v = args[++i];
        long long n = 0;
        if (a == "-c") {
            if (!number(v, 0, 15, n))
                return Error{-1, "-c '" + std::string(v) + "': channel must be 0 to 15"};
            o.channel = static_cast<int>(n);
        } else if (a == "-n") {
            if (!number(v, 2, 10000000, n))
                return Error{-1, "-n '" + std::string(v) + "': count must be 2 to 10000000"};
            o.count = static_cast<unsigned long>(n);
        } else if (a == "-o") {
            if (ends_with(v, ".svg"))
                o.format = PlotFormat::svg;
            else if (ends_with(v, ".png"))
                o.format = PlotFormat::png;
            else
                return Error{-1, "-o '" + std::string(v) + "': the file name must end in .svg or .png"};
            o.output = v;
        } else if (a == "-T") {
            o.title = v;
        } else {  // -s WxH
            size_t x = v.find('x');
            long long w = 0, h = 0;
            if (x == std::string_view::npos || !number(v.substr(0, x), 100, 10000, w) ||
                !number(v.substr(x + 1), 100, 10000, h))
                return Error{-1, "-s '" + std::string(v) + "': size must be WIDTHxHEIGHT, 100 to 10000 pixels each"};
            o.width = static_cast<int>(w);
            o.height = static_cast<int>(h);
        }
    }
    if (o.title.empty())
        o.title = "sampler." + std::to_string(o.channel);
    return o;
}

}  // namespace hal
