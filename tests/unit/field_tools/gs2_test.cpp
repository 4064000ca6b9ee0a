// SPDX-License-Identifier: GPL-2.0-or-later
// gs2_vfd(1): options, register decoding, speed arithmetic, at-speed.
#include <gtest/gtest.h>

#include <vector>

#include "gs2_drive.hpp"
#include "gs2_options.hpp"

using namespace hal::gs2;

namespace {

hal::Result<Gs2Options> parse(std::vector<const char*> args)
{
    args.insert(args.begin(), "gs2_vfd");
    return parse_gs2_options(std::span<char* const>(const_cast<char* const*>(args.data()), args.size()));
}

}  // namespace

TEST(Gs2Options, DefaultsAreThePages)
{
    auto o = parse({});
    ASSERT_TRUE(o);
    EXPECT_EQ(o->bits, 8);
    EXPECT_EQ(o->device, "/dev/ttyS0");
    EXPECT_EQ(o->name, "gs2_vfd");
    EXPECT_EQ(o->parity, 'O');
    EXPECT_EQ(o->rate, 38400);
    EXPECT_EQ(o->stopbits, 1);
    EXPECT_EQ(o->target, 1);
    EXPECT_FALSE(o->verbose);
}

TEST(Gs2Options, ShortAndLongForms)
{
    auto o = parse({"-b", "7", "-device", "/dev/ttyUSB0", "--name", "spindle", "-p", "even", "-rate", "9600",
                    "-s", "2", "--target", "3", "-g"});
    ASSERT_TRUE(o);
    EXPECT_EQ(o->bits, 7);
    EXPECT_EQ(o->device, "/dev/ttyUSB0");
    EXPECT_EQ(o->name, "spindle");
    EXPECT_EQ(o->parity, 'E');
    EXPECT_EQ(o->rate, 9600);
    EXPECT_EQ(o->stopbits, 2);
    EXPECT_EQ(o->target, 3);
    EXPECT_TRUE(o->debug);
    EXPECT_TRUE(o->verbose);     // -g sets verbose too
}

TEST(Gs2Options, BaudRateMustBeAStandardOne)
{
    auto o = parse({"-r", "14400"});
    ASSERT_FALSE(o);
    EXPECT_EQ(o.error().message,
              "-rate: 14400 baud is not one of 110, 300, 600, 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200");
    EXPECT_TRUE(parse({"-r", "115200"}));
    EXPECT_TRUE(parse({"-r", "110"}));
}

TEST(Gs2Options, RefusesBadValues)
{
    EXPECT_EQ(parse({"-b", "9"}).error().message, "-bits: 9 data bits; must be 5 to 8");
    EXPECT_EQ(parse({"-p", "mark"}).error().message, "-parity: 'mark'; use even, odd or none");
    EXPECT_EQ(parse({"-s", "3"}).error().message, "-stopbits: 3; must be 1 or 2");
    EXPECT_EQ(parse({"-t", "0"}).error().message, "-target: 0; a Modbus target is 1 to 247");
    EXPECT_EQ(parse({"-x"}).error().message, "unknown option '-x'");
    EXPECT_EQ(parse({"-d"}).error().message, "-device needs a value");
    EXPECT_EQ(parse({"-r", "fast"}).error().message, "-rate: 'fast' is not a number");
}

TEST(Gs2Drive, DecodesTheStatusBlock)
{
    uint16_t r[status_count] = {4, 163, 600, 599, 35, 3251, 2301, 1725, 0x5678, 0x0001, 855, 123, 104};
    Status s = decode_status(r);
    EXPECT_EQ(s.status1, 4);
    EXPECT_EQ(s.status2, 163);
    EXPECT_DOUBLE_EQ(s.freq_cmd, 60.0);
    EXPECT_DOUBLE_EQ(s.freq_out, 59.9);
    EXPECT_DOUBLE_EQ(s.current, 3.5);
    EXPECT_DOUBLE_EQ(s.dc_bus, 325.1);
    EXPECT_DOUBLE_EQ(s.volts_out, 230.1);
    EXPECT_DOUBLE_EQ(s.rpm, 1725);
    EXPECT_DOUBLE_EQ(s.scale_freq, 0x15678);
    EXPECT_DOUBLE_EQ(s.power_factor, 85.5);
    EXPECT_DOUBLE_EQ(s.load, 12.3);
    EXPECT_EQ(s.firmware, 104);
    EXPECT_FALSE(s.is_stopped);
    r[st_freq_out] = 0;
    EXPECT_TRUE(decode_status(r).is_stopped);
}

TEST(Gs2Drive, SpeedIsScaledByTheNameplate)
{
    EXPECT_EQ(speed_to_register(1730, 60, 1730), 600);
    EXPECT_EQ(speed_to_register(865, 60, 1730), 300);
    EXPECT_EQ(speed_to_register(-865, 60, 1730), 300);     // direction is separate
    EXPECT_EQ(speed_to_register(1000, 60, 0), 0);          // unusable nameplate: stop
    EXPECT_EQ(speed_to_register(1e9, 60, 1730), 65535);
}

TEST(Gs2Drive, DirectionFromTheTwoPins)
{
    EXPECT_EQ(direction_register(true, false), 0);
    EXPECT_EQ(direction_register(false, true), 1);
    EXPECT_EQ(direction_register(false, false), 1);        // "0 for REV"
    EXPECT_EQ(direction_register(true, true), 1);
}

TEST(Gs2Drive, AtSpeedWaitsForAckDelayAndTolerance)
{
    EXPECT_FALSE(at_speed(60, 60, 0.01, 1, 2));
    EXPECT_TRUE(at_speed(60, 60, 0.01, 2, 2));
    EXPECT_TRUE(at_speed(59.5, 60, 0.01, 5, 2));
    EXPECT_FALSE(at_speed(59.3, 60, 0.01, 5, 2));
    EXPECT_TRUE(at_speed(0, 0, 0.01, 5, 2));
}
