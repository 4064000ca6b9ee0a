// SPDX-License-Identifier: GPL-2.0-or-later
// Typed reads (ini-and-launch.md 1.1 "Typed conversions"): reals, %i integers,
// booleans, fallbacks, and the FILE:LINE errors of malformed values.
#include <gtest/gtest.h>

#include "ini/ini_file.hpp"
#include "ini_of.hpp"

using hal::ini::IniFile;

TEST(IniValues, Doubles)
{
    IniFile ini = ini_of("[T]\nA = 1.5\nB = -2e3\nC = .25\nD = 7\nE = 0.001 (mm per step)\n");
    EXPECT_DOUBLE_EQ(*ini.get_double("T", "A", 0), 1.5);
    EXPECT_DOUBLE_EQ(*ini.get_double("T", "B", 0), -2000);
    EXPECT_DOUBLE_EQ(*ini.get_double("T", "C", 0), 0.25);
    EXPECT_DOUBLE_EQ(*ini.get_double("T", "D", 0), 7);
    EXPECT_DOUBLE_EQ(*ini.get_double("T", "E", 0), 0.001);   // scanf ignores what follows a blank
    EXPECT_DOUBLE_EQ(*ini.get_double("T", "NONE", 3.25), 3.25);
}

TEST(IniValues, MalformedDoubleNamesFileLineAndKey)
{
    IniFile ini = ini_of("[TRAJ]\n\nMAX_VELOCITY = abc\nB = 1.5mm\nC =\nD = nan\nE = 1e999\n");
    auto a = ini.get_double("TRAJ", "MAX_VELOCITY", 1);
    ASSERT_FALSE(a);
    EXPECT_EQ(a.error().message, "m.ini:3: [TRAJ]MAX_VELOCITY: 'abc' is not a number");
    EXPECT_EQ(ini.get_double("TRAJ", "B", 1).error().message, "m.ini:4: [TRAJ]B: '1.5mm' is not a number");
    EXPECT_EQ(ini.get_double("TRAJ", "C", 1).error().message, "m.ini:5: [TRAJ]C: '' is not a number");
    EXPECT_EQ(ini.get_double("TRAJ", "D", 1).error().message, "m.ini:6: [TRAJ]D: 'nan' is not a number");
    EXPECT_EQ(ini.get_double("TRAJ", "E", 1).error().message, "m.ini:7: [TRAJ]E: '1e999' is not a number");
}

TEST(IniValues, IntegersAsPercentI)
{
    IniFile ini = ini_of("[E]\nA = 42\nB = 0x1F\nC = 010\nD = -3\nE = 0\n");
    EXPECT_EQ(*ini.get_int("E", "A", 0), 42);
    EXPECT_EQ(*ini.get_int("E", "B", 0), 31);
    EXPECT_EQ(*ini.get_int("E", "C", 0), 8);   // leading zero: octal
    EXPECT_EQ(*ini.get_int("E", "D", 0), -3);
    EXPECT_EQ(*ini.get_int("E", "E", 9), 0);
    EXPECT_EQ(*ini.get_int("E", "NONE", 9), 9);
}

TEST(IniValues, MalformedIntegers)
{
    IniFile ini = ini_of("[E]\nA = 1.5\nB = ten\nC = 99999999999999999999999\nD = 09\n");
    EXPECT_EQ(ini.get_int("E", "A", 0).error().message, "m.ini:2: [E]A: '1.5' is not an integer");
    EXPECT_EQ(ini.get_int("E", "B", 0).error().message, "m.ini:3: [E]B: 'ten' is not an integer");
    EXPECT_EQ(ini.get_int("E", "C", 0).error().message,
              "m.ini:4: [E]C: '99999999999999999999999' is out of range");
    EXPECT_EQ(ini.get_int("E", "D", 0).error().message, "m.ini:5: [E]D: '09' is not an integer");
}

TEST(IniValues, Booleans)
{
    IniFile ini = ini_of("[B]\nA = YES\nB = no\nC = True\nD = FALSE\nE = 1\nF = 0\nG = on\nH = Off\nI = 5\nJ = 0x0\n");
    EXPECT_TRUE(*ini.get_bool("B", "A", false));
    EXPECT_FALSE(*ini.get_bool("B", "B", true));
    EXPECT_TRUE(*ini.get_bool("B", "C", false));
    EXPECT_FALSE(*ini.get_bool("B", "D", true));
    EXPECT_TRUE(*ini.get_bool("B", "E", false));
    EXPECT_FALSE(*ini.get_bool("B", "F", true));
    EXPECT_TRUE(*ini.get_bool("B", "G", false));
    EXPECT_FALSE(*ini.get_bool("B", "H", true));
    EXPECT_TRUE(*ini.get_bool("B", "I", false));   // any integer: non-zero is true
    EXPECT_FALSE(*ini.get_bool("B", "J", true));
    EXPECT_TRUE(*ini.get_bool("B", "NONE", true));
    EXPECT_FALSE(*ini.get_bool("B", "NONE", false));
}

TEST(IniValues, MalformedBoolean)
{
    IniFile ini = ini_of("[EMCIO]\nRANDOM_TOOLCHANGER = maybe\n");
    auto r = ini.get_bool("EMCIO", "RANDOM_TOOLCHANGER", false);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message,
              "m.ini:2: [EMCIO]RANDOM_TOOLCHANGER: 'maybe' is not a boolean (YES/NO, TRUE/FALSE, ON/OFF, 1/0)");
}

TEST(IniValues, TypedReadsUseTheFirstOccurrence)
{
    IniFile ini = ini_of("[S]\nK = 1\nK = bad\n");
    EXPECT_EQ(*ini.get_int("S", "K", 0), 1);
}
