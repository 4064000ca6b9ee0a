// SPDX-License-Identifier: GPL-2.0-or-later
// shuttlexpress(1): report decoding and the jog counter.
#include <gtest/gtest.h>

#include "shuttle_report.hpp"

using namespace hal::shuttle;

TEST(ShuttleReport, ButtonsAndSpringWheel)
{
    uint8_t raw[report_size] = {0xf9, 17, 0, 0x50, 0x01};   // spring -7, buttons 0, 2, 4
    Report r = decode_report(raw);
    EXPECT_EQ(r.spring, -7);
    EXPECT_EQ(r.jog, 17);
    EXPECT_TRUE(r.buttons[0]);
    EXPECT_FALSE(r.buttons[1]);
    EXPECT_TRUE(r.buttons[2]);
    EXPECT_FALSE(r.buttons[3]);
    EXPECT_TRUE(r.buttons[4]);
}

TEST(ShuttleJog, FirstReportOnlySetsTheReference)
{
    JogCounter j;
    EXPECT_EQ(j.update(200), 0);
    EXPECT_EQ(j.update(203), 3);
    EXPECT_EQ(j.update(201), 1);
}

TEST(ShuttleJog, CounterWrapsBothWays)
{
    JogCounter j;
    j.update(254);
    EXPECT_EQ(j.update(1), 3);
    EXPECT_EQ(j.update(255), 1);
}
