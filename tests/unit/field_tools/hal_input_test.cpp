// SPDX-License-Identifier: GPL-2.0-or-later
// hal_input(1): inputspecs, device matching, axis arithmetic.
#include <gtest/gtest.h>

#include <vector>

#include "input_axes.hpp"
#include "input_spec.hpp"

using namespace hal::input;

namespace {

hal::Result<std::vector<InputSpec>> parse(std::vector<const char*> args)
{
    args.insert(args.begin(), "hal_input");
    return parse_input_args(std::span<char* const>(const_cast<char* const*>(args.data()), args.size()));
}

std::vector<DeviceInfo> devices()
{
    return {
        {10, "/dev/input/event10", "Logitech USB Mouse", "usb-0000:00:1d.0-1/input0", format_id(3, 0x46d, 0xc00e, 0x111)},
        {3, "/dev/input/event3", "Logitech USB Mouse", "usb-0000:00:1d.0-2/input0", format_id(3, 0x46d, 0xc00e, 0x111)},
        {1, "/dev/input/event1", "AT Translated Set 2 keyboard", "isa0060/serio0/input0", format_id(0x11, 1, 1, 0xab41)},
    };
}

}  // namespace

TEST(HalInputSpec, FormsOfInputspec)
{
    auto s = parse({"-KL", "+keyboard", "5", "Mouse:1", "serio*/input0"});
    ASSERT_TRUE(s);
    ASSERT_EQ(s->size(), 4u);
    EXPECT_TRUE((*s)[0].exclusive);
    EXPECT_EQ((*s)[0].pattern, "keyboard");
    EXPECT_TRUE((*s)[0].features.keys);
    EXPECT_TRUE((*s)[0].features.leds);
    EXPECT_FALSE((*s)[0].features.abs);
    EXPECT_FALSE((*s)[0].features.rel);
    EXPECT_EQ((*s)[1].event_number, 5);
    EXPECT_TRUE((*s)[1].features.abs);        // the option applies to one spec only
    EXPECT_EQ((*s)[2].pattern, "Mouse");
    EXPECT_EQ((*s)[2].index, 1);
    EXPECT_EQ((*s)[3].pattern, "serio*/input0");
}

TEST(HalInputSpec, RefusesBadArguments)
{
    EXPECT_EQ(parse({}).error().message, "no inputspec given");
    EXPECT_EQ(parse({"-KX", "kbd"}).error().message,
              "option '-KX': 'X' is not one of K (keys), R (relative), A (absolute), L (LEDs)");
    EXPECT_EQ(parse({"kbd", "-K"}).error().message, "a -KRAL option must be followed by an inputspec");
    EXPECT_EQ(parse({"+"}).error().message, "inputspec '+' names no device");
}

TEST(HalInputMatch, IndexCountsMatchesInEventOrder)
{
    auto s = parse({"Mouse", "Mouse:0", "Mouse:1", "Mouse:2"});
    ASSERT_TRUE(s);
    EXPECT_EQ(select_device((*s)[0], devices())->event_number, 3);
    EXPECT_EQ(select_device((*s)[1], devices())->event_number, 3);
    EXPECT_EQ(select_device((*s)[2], devices())->event_number, 10);
    EXPECT_FALSE(select_device((*s)[3], devices()));
}

TEST(HalInputMatch, NamePhysIdAndPatterns)
{
    auto s = parse({"Vendor=046d Product=c00e", "isa*/serio0/input0", "1", "SpaceBall"});
    ASSERT_TRUE(s);
    EXPECT_EQ(select_device((*s)[0], devices())->event_number, 3);
    EXPECT_EQ(select_device((*s)[1], devices())->event_number, 1);
    EXPECT_EQ(select_device((*s)[2], devices())->devnode, "/dev/input/event1");
    EXPECT_FALSE(select_device((*s)[3], devices()));
}

TEST(HalInputAxes, DefaultsMapTheRangeToPlusMinusOne)
{
    AbsDefaults d = abs_defaults(0, 255);
    EXPECT_DOUBLE_EQ(abs_position(255, d.offset, d.scale), 1.0);
    EXPECT_DOUBLE_EQ(abs_position(0, d.offset, d.scale), -1.0);
    d = abs_defaults(-100, 100);
    EXPECT_DOUBLE_EQ(d.offset, 0);
    EXPECT_DOUBLE_EQ(abs_position(50, d.offset, d.scale), 0.5);
}

TEST(HalInputAxes, FlatAndFuzz)
{
    EXPECT_EQ(abs_counts(0, 3, 0, 0, 5), 0);     // inside flat: the offset
    EXPECT_EQ(abs_counts(0, 6, 0, 0, 5), 6);
    EXPECT_EQ(abs_counts(50, 52, 0, 4, 0), 50);  // moved less than fuzz
    EXPECT_EQ(abs_counts(50, 54, 0, 4, 0), 54);
}

TEST(HalInputAxes, RelativePrecisionAndAbsoluteFilter)
{
    EXPECT_EQ(rel_sign_extend(0xff, 8), -1);
    EXPECT_EQ(rel_sign_extend(0x7f, 8), 127);
    EXPECT_EQ(rel_sign_extend(-3, 32), -3);
    RelState s;
    rel_event(s, 2, 32, false);
    rel_event(s, 2, 32, false);
    EXPECT_EQ(s.counts, 4);
    rel_event(s, 2, 32, true);                   // same as last: a repeat
    EXPECT_EQ(s.counts, 4);
    rel_event(s, 0xfe, 8, true);
    EXPECT_EQ(s.counts, 2);
    EXPECT_EQ(s.last, 0xfe);
    EXPECT_DOUBLE_EQ(rel_position(10, 4), 2.5);
}
