// SPDX-License-Identifier: GPL-2.0-or-later
// plot_script.hpp - what halplot hands gnuplot: the data file (one row per sample,
// time then one column per channel) and the script that draws one trace per
// channel, legend from the channels' names. Pure, so the unit tests check both.
#pragma once

#include <string>
#include <vector>

#include "plot_options.hpp"

namespace hal {

struct PlotChannel {
    std::string label;   // legend: the pin feeding the channel, or its signal, or the sampler pin
    char type;           // 'f', 'b', 's' or 'u' (sampler cfg letter)
};

// Rows of values as numbers (bits 0/1); period_ns: the sampler's thread period.
std::string plot_data(const std::vector<std::vector<double>>& rows, long long period_ns);

// A gnuplot script that reads DATA_FILE and writes opt.output.
std::string plot_script(const PlotOptions& opt, const std::vector<PlotChannel>& channels,
                        const std::string& data_file);

// A string as a gnuplot single-quoted literal.
std::string gnuplot_quote(const std::string& s);

}  // namespace hal
