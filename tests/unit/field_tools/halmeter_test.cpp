// SPDX-License-Identifier: GPL-2.0-or-later
// halmeter(1) options and terminal output.
#include <gtest/gtest.h>

#include <vector>

#include "meter_options.hpp"
#include "meter_terminal.hpp"

using namespace hal::meter;

namespace {

hal::Result<MeterOptions> parse(std::vector<const char*> args)
{
    args.insert(args.begin(), "halmeter");
    return parse_meter_options(std::span<char* const>(const_cast<char* const*>(args.data()), args.size()));
}

}  // namespace

TEST(HalmeterOptions, NoArgumentsIsABlankWindow)
{
    auto o = parse({});
    ASSERT_TRUE(o);
    EXPECT_EQ(o->item.kind, Kind::none);
    EXPECT_FALSE(o->small);
    EXPECT_EQ(o->width, 270);
}

TEST(HalmeterOptions, SmallWindowWithGeometryAndWidth)
{
    auto o = parse({"-s", "pin", "parport.0.pin-03-out", "-g", "100", "500", "400"});
    ASSERT_TRUE(o);
    EXPECT_TRUE(o->small);
    EXPECT_EQ(o->item.kind, Kind::pin);
    EXPECT_EQ(o->item.name, "parport.0.pin-03-out");
    EXPECT_TRUE(o->has_geometry);
    EXPECT_EQ(o->x, 100);
    EXPECT_EQ(o->y, 500);
    EXPECT_EQ(o->width, 400);
}

TEST(HalmeterOptions, GeometryWithoutWidthKeepsTheDefault)
{
    auto o = parse({"-g", "10", "20", "sig", "x"});
    ASSERT_TRUE(o);
    EXPECT_EQ(o->width, 270);
    EXPECT_EQ(o->item.kind, Kind::sig);
}

TEST(HalmeterOptions, SmallNeedsAnItem)
{
    auto o = parse({"-s"});
    ASSERT_FALSE(o);
    EXPECT_EQ(o.error().message, "-s needs an item: pin, sig or param NAME");
}

TEST(HalmeterOptions, TerminalModeWithCountAndInterval)
{
    auto o = parse({"-l", "-n", "3", "-i", "20", "param", "p"});
    ASSERT_TRUE(o);
    EXPECT_TRUE(o->terminal);
    EXPECT_TRUE(o->lines);
    EXPECT_EQ(o->count, 3);
    EXPECT_EQ(o->interval_ms, 20);
    EXPECT_EQ(o->item.kind, Kind::param);
}

TEST(HalmeterOptions, RefusesBadValues)
{
    EXPECT_EQ(parse({"-g", "1"}).error().message, "-g needs X and Y positions (and optionally a width)");
    EXPECT_EQ(parse({"-t", "-i", "0", "pin", "a"}).error().message, "-i needs a number from 1 to 3600000, not '0'");
    EXPECT_EQ(parse({"-n", "2", "pin", "a"}).error().message, "-n applies to terminal mode only (add -t)");
    EXPECT_EQ(parse({"pin", "a", "sig", "b"}).error().message, "only one item can be shown; 'sig' is a second one");
    EXPECT_EQ(parse({"pins", "a"}).error().message, "unexpected argument 'pins' (expected pin, sig or param NAME)");
    EXPECT_EQ(parse({"-t"}).error().message, "terminal mode needs an item: pin, sig or param NAME");
}

TEST(HalmeterTerminal, InPlaceRedrawsTheLine)
{
    EXPECT_EQ(terminal_update({Kind::pin, "a.b"}, "1.5", true), "\ra.b = 1.5\033[K");
}

TEST(HalmeterTerminal, LinesModePrintsTheValueOnly)
{
    EXPECT_EQ(terminal_update({Kind::sig, "x"}, "TRUE", false), "TRUE\n");
}
