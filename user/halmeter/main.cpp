// SPDX-License-Identifier: GPL-2.0-or-later
// halmeter(1): observe one HAL pin, signal or parameter, in a GTK window or (-t) on
// the terminal. Parses the options, attaches to the HAL and hands over.
#include <cstdio>

#include "meter_options.hpp"
#include "meter_source.hpp"
#include "meter_terminal.hpp"
#include "meter_window.hpp"

int main(int argc, char** argv)
{
    using namespace hal::meter;
    auto opts = parse_meter_options(std::span<char* const>(argv, static_cast<size_t>(argc)));
    if (!opts) {
        std::fprintf(stderr, "halmeter: %s\n%s", opts.error().message.c_str(), meter_usage);
        return 1;
    }
    if (opts->help) {
        std::fputs(meter_usage, stdout);
        return 0;
    }
    if (auto r = attach_hal(); !r) {
        std::fprintf(stderr, "halmeter: %s\n", r.error().message.c_str());
        return 1;
    }
    if (opts->item.kind != Kind::none) {
        if (auto v = read_item(opts->item); !v) {
            std::fprintf(stderr, "halmeter: %s\n", v.error().message.c_str());
            return 1;
        }
    }
    if (opts->terminal)
        return run_terminal(*opts);
    return run_window(*opts, argc, argv);
}
