// SPDX-License-Identifier: GPL-2.0-or-later
// plot_options.hpp - halplot(1) command line:
//   halplot [-c CHAN] [-n COUNT] [-o FILE.svg|FILE.png] [-T TITLE] [-s WxH]
#pragma once

#include <span>
#include <string>

#include "hal/result.hpp"

namespace hal {

enum class PlotFormat { svg, png };

struct PlotOptions {
    int channel = 0;                       // -c: sampler FIFO number
    unsigned long count = 1000;            // -n: samples to plot
    std::string output = "halplot.svg";    // -o: the format follows the extension
    PlotFormat format = PlotFormat::svg;
    std::string title;                     // -T: "" = "sampler.N"
    int width = 800, height = 480;         // -s WxH, pixels
    bool help = false;
};

// args[0] is the program name. Pure: no I/O.
Result<PlotOptions> parse_plot_options(std::span<char* const> args);

inline constexpr const char* plot_usage =
    "usage: halplot [-c CHAN] [-n COUNT] [-o FILE.svg|FILE.png] [-T TITLE] [-s WxH]\n"
    "  -c CHAN   read sampler FIFO CHAN (default 0)\n"
    "  -n COUNT  plot COUNT samples (default 1000)\n"
    "  -o FILE   write the chart to FILE, SVG or PNG by its extension (default halplot.svg)\n"
    "  -T TITLE  title of the chart (default sampler.CHAN)\n"
    "  -s WxH    size in pixels (default 800x480)\n";

}  // namespace hal
