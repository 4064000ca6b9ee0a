// SPDX-License-Identifier: GPL-2.0-or-later
// The launcher's command line (emc(1), ini-and-launch.md 3.1).
#include <gtest/gtest.h>

#include "options.hpp"

using hal::launcher::parse_options;
using V = std::vector<std::string>;

TEST(LauncherOptions, FlagsAndIni)
{
    auto o = parse_options(V{"-v", "-k", "-r", "m.ini"});
    ASSERT_TRUE(o);
    EXPECT_TRUE(o->verbose);
    EXPECT_TRUE(o->keep_going);
    EXPECT_TRUE(o->no_redirect);
    EXPECT_FALSE(o->trace);
    EXPECT_EQ(o->inifile, "m.ini");
}

TEST(LauncherOptions, DebugImpliesVerboseAndFlagsBundle)
{
    auto o = parse_options(V{"-dk", "m.ini"});
    ASSERT_TRUE(o);
    EXPECT_TRUE(o->trace);
    EXPECT_TRUE(o->verbose);
    EXPECT_TRUE(o->keep_going);
}

TEST(LauncherOptions, HalDirsInOrder)
{
    auto o = parse_options(V{"-H", "a", "-Hb", "m.ini"});
    ASSERT_TRUE(o);
    EXPECT_EQ(o->hal_dirs, (V{"a", "b"}));
    EXPECT_EQ(parse_options(V{"-H"}).error().message, "-H needs a directory");
}

TEST(LauncherOptions, LastConfig)
{
    EXPECT_TRUE(parse_options(V{"-l"})->last);
    EXPECT_TRUE(parse_options(V{"-"})->last);
    EXPECT_EQ(parse_options(V{"-l", "m.ini"}).error().message, "-l and an INI file given: choose one");
}

TEST(LauncherOptions, Errors)
{
    EXPECT_EQ(parse_options(V{"-x"}).error().message, "unknown option '-x'");
    EXPECT_EQ(parse_options(V{"a.ini", "b.ini"}).error().message, "more than one INI file given ('b.ini')");
    EXPECT_FALSE(parse_options(V{"-t", "tpmod"}));
    EXPECT_FALSE(parse_options(V{"-m", "homemod"}));
}

TEST(LauncherOptions, Help)
{
    EXPECT_TRUE(parse_options(V{"-h"})->help);
    EXPECT_TRUE(parse_options(V{"--help"})->help);
    EXPECT_NE(hal::launcher::usage_text("linuxcnc").find("usage: linuxcnc "), std::string::npos);
}
