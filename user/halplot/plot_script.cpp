// SPDX-License-Identifier: GPL-2.0-or-later
// plot_script.cpp - see plot_script.hpp.
#include "plot_script.hpp"

#include <cstdio>
#include <sstream>

namespace hal {

std::string gnuplot_quote(const std::string& s)
{
    std::string out = "'";
    for (char c : s) {
        if (c == '\'')
            out += "''";  // gnuplot's escape inside single quotes
        else if (c == '\n' || c == '\r')
            out += ' ';
        else
            out += c;
    }
    return out + "'";
}

std::string plot_data(const std::vector<std::vector<double>>& rows, long long period_ns)
{
    std::string out;
    char buf[64];
    for (size_t i = 0; i < rows.size(); i++) {
        // time of sample i in seconds, exact for any period up to seconds
        std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(i) * static_cast<double>(period_ns) * 1e-9);
        out += buf;
        for (double v : rows[i]) {
            std::snprintf(buf, sizeof buf, " %.17g", v);
            out += buf;
        }
        out += '\n';
    }
    return out;
}

std::string plot_script(const PlotOptions& opt, const std::vector<PlotChannel>& channels,
                        const std::string& data_file)
{
    std::ostringstream s;
    if (opt.format == PlotFormat::svg)
        s << "set terminal svg size " << opt.width << "," << opt.height
          << " noenhanced font 'sans,11' background '#ffffff'\n";
    else
        s << "set terminal pngcairo size " << opt.width << "," << opt.height
          << " noenhanced font 'sans,10'\n";
    s << "set output " << gnuplot_quote(opt.output) << "\n"
      << "set title " << gnuplot_quote(opt.title) << "\n"
      << "set xlabel 'time (s)'\n"
      << "set ylabel 'value'\n"
      << "set grid\n"
      // a margin above and below, so bits at 0 and 1 do not vanish into the border
      << "set offsets 0, 0, graph 0.05, graph 0.05\n"
      << "set key outside right top box\n"
      << "plot ";
    for (size_t i = 0; i < channels.size(); i++) {
        // bits and integers hold their value for a period: steps, not ramps
        const char* style = channels[i].type == 'f' ? "lines" : "steps";
        s << (i ? ", \\\n     " : "") << gnuplot_quote(data_file) << " using 1:" << i + 2
          << " with " << style << " linewidth 1.5 title " << gnuplot_quote(channels[i].label);
    }
    s << "\n";
    return s.str();
}

}  // namespace hal
