// SPDX-License-Identifier: GPL-2.0-or-later
#include <gtest/gtest.h>

#include <vector>

#include "plot_options.hpp"
#include "plot_script.hpp"

namespace {

hal::Result<hal::PlotOptions> parse(std::vector<const char*> args)
{
    args.insert(args.begin(), "halplot");
    return hal::parse_plot_options(
        std::span<char* const>(const_cast<char* const*>(args.data()), args.size()));
}

TEST(PlotOptions, Defaults)
{
    auto o = parse({});
    ASSERT_TRUE(o);
    EXPECT_EQ(o->channel, 0);
    EXPECT_EQ(o->count, 1000u);
    EXPECT_EQ(o->output, "halplot.svg");
    EXPECT_EQ(o->format, hal::PlotFormat::svg);
    EXPECT_EQ(o->title, "sampler.0");
}

TEST(PlotOptions, AllOptions)
{
    auto o = parse({"-c", "3", "-n", "50", "-o", "x.png", "-T", "my plot", "-s", "640x400"});
    ASSERT_TRUE(o);
    EXPECT_EQ(o->channel, 3);
    EXPECT_EQ(o->count, 50u);
    EXPECT_EQ(o->format, hal::PlotFormat::png);
    EXPECT_EQ(o->title, "my plot");
    EXPECT_EQ(o->width, 640);
    EXPECT_EQ(o->height, 400);
}

TEST(PlotOptions, Refused)
{
    for (auto args : std::vector<std::vector<const char*>>{{"-c", "16"}, {"-c", "x"}, {"-n", "1"},
                                                           {"-n", "5k"}, {"-o", "a.jpg"}, {"-o", ".svg"},
                                                           {"-s", "800"}, {"-s", "50x50"}, {"-T"}, {"extra"}}) {
        auto o = parse(args);
        EXPECT_FALSE(o) << args[0];
        if (!o) {
            EXPECT_EQ(o.error().message.find('\n'), std::string::npos);
        }
    }
}

TEST(PlotData, TimeFromPeriod)
{
    std::string d = hal::plot_data({{1.5, 0}, {-2, 1}, {0.25, 1}}, 250000);
    EXPECT_EQ(d, "0 1.5 0\n0.00025 -2 1\n0.0005 0.25 1\n");
}

TEST(PlotScript, OneTracePerChannelWithLegend)
{
    auto o = parse({"-o", "out.svg", "-T", "it's"});
    ASSERT_TRUE(o);
    std::string s = hal::plot_script(*o, {{"siggen.0.sine", 'f'}, {"clock", 'b'}}, "/tmp/d.dat");
    EXPECT_NE(s.find("set terminal svg size 800,480"), std::string::npos);
    EXPECT_NE(s.find("set output 'out.svg'"), std::string::npos);
    EXPECT_NE(s.find("set title 'it''s'"), std::string::npos);
    EXPECT_NE(s.find("'/tmp/d.dat' using 1:2 with lines linewidth 1.5 title 'siggen.0.sine'"), std::string::npos);
    EXPECT_NE(s.find("'/tmp/d.dat' using 1:3 with steps linewidth 1.5 title 'clock'"), std::string::npos);
    EXPECT_EQ(s.find("using 1:4"), std::string::npos);
}

TEST(PlotScript, PngTerminal)
{
    auto o = parse({"-o", "a.png"});
    ASSERT_TRUE(o);
    EXPECT_NE(hal::plot_script(*o, {{"x", 'f'}}, "d").find("set terminal pngcairo"), std::string::npos);
}

TEST(PlotScript, QuoteStripsNewlines)
{
    EXPECT_EQ(hal::gnuplot_quote("a\nb'c"), "'a b''c'");
}

}  // namespace
