// SPDX-License-Identifier: GPL-2.0-or-later
// options_test.cpp - halcmd/halrun option parsing (halcmd(1) OPTIONS).
#include <gtest/gtest.h>

#include "options.hpp"

using namespace hal::halcmd;
using V = std::vector<std::string>;

static Options parse_ok(V args)
{
    auto o = parse_halcmd_options(args);
    EXPECT_TRUE(o.has_value()) << (o ? "" : o.error().message);
    return o ? *o : Options{};
}

static std::string parse_err(V args)
{
    auto o = parse_halcmd_options(args);
    EXPECT_FALSE(o.has_value());
    return o ? "" : o.error().message;
}

TEST(HalcmdOptions, NoArgumentsMeansInteractive)
{
    Options o = parse_ok({});
    EXPECT_FALSE(o.from_file);
    EXPECT_TRUE(o.command.empty());
    EXPECT_EQ(o.verbosity, Verbosity::errors);
}

TEST(HalcmdOptions, CommandWordsFollowOptions)
{
    Options o = parse_ok({"-k", "setp", "-x", "1"});
    EXPECT_TRUE(o.keep_going);
    EXPECT_EQ(o.command, (V{"setp", "-x", "1"}));   // options stop at the command
}

TEST(HalcmdOptions, FileOptionTakesOptionalFile)
{
    Options o = parse_ok({"-f", "x.hal"});
    EXPECT_TRUE(o.from_file);
    EXPECT_EQ(o.file, "x.hal");
    Options s = parse_ok({"-f"});
    EXPECT_TRUE(s.from_file);
    EXPECT_EQ(s.file, "");
}

TEST(HalcmdOptions, ClusteredFlags)
{
    Options o = parse_ok({"-kfs", "a.hal"});
    EXPECT_TRUE(o.keep_going);
    EXPECT_TRUE(o.from_file);
    EXPECT_TRUE(o.script_mode);
    EXPECT_EQ(o.file, "a.hal");
}

TEST(HalcmdOptions, InifileAttachedOrSeparate)
{
    EXPECT_EQ(parse_ok({"-i", "m.ini", "show"}).inifile, "m.ini");
    EXPECT_EQ(parse_ok({"-im.ini", "show"}).inifile, "m.ini");
    EXPECT_EQ(parse_ok({"-ki", "m.ini", "-f", "a.hal"}).file, "a.hal");
}

TEST(HalcmdOptions, InifileWithoutArgumentIsAnError)
{
    EXPECT_NE(parse_err({"-i"}).find("-i needs an inifile"), std::string::npos);
}

TEST(HalcmdOptions, VerbosityFlags)
{
    EXPECT_EQ(parse_ok({"-Q"}).verbosity, Verbosity::silent);
    EXPECT_EQ(parse_ok({"-v"}).verbosity, Verbosity::verbose);
    EXPECT_EQ(parse_ok({"-V"}).verbosity, Verbosity::debug);
    EXPECT_EQ(parse_ok({"-V", "-q"}).verbosity, Verbosity::errors);
}

TEST(HalcmdOptions, ReleaseMutex)
{
    EXPECT_TRUE(parse_ok({"-R"}).release_mutex);
}

TEST(HalcmdOptions, HelpWithOptionalTopic)
{
    Options o = parse_ok({"-h"});
    EXPECT_TRUE(o.help);
    EXPECT_EQ(o.help_topic, "");
    EXPECT_EQ(parse_ok({"-h", "net"}).help_topic, "net");
    EXPECT_NE(parse_err({"-h", "net", "setp"}).find("at most one"), std::string::npos);
}

TEST(HalcmdOptions, UnknownOptionNamesIt)
{
    EXPECT_NE(parse_err({"-x"}).find("'-x'"), std::string::npos);
}

TEST(HalcmdOptions, HalrunOnlyOptionsAreRefused)
{
    EXPECT_NE(parse_err({"-U"}).find("halrun only"), std::string::npos);
    EXPECT_NE(parse_err({"-I"}).find("halrun only"), std::string::npos);
}

TEST(HalcmdOptions, WordsAfterTheFileAreIgnored)
{
    Options o = parse_ok({"-f", "a.hal", "b.hal", "show"});
    EXPECT_TRUE(o.from_file);
    EXPECT_EQ(o.file, "a.hal");
    EXPECT_TRUE(o.command.empty());
}

TEST(HalcmdOptions, DoubleDashEndsOptions)
{
    EXPECT_EQ(parse_ok({"--", "-k"}).command, V{"-k"});
}

TEST(HalrunOptions, HalFileMeansDashF)
{
    auto h = parse_halrun_options(V{"test.hal"});
    ASSERT_TRUE(h);
    EXPECT_TRUE(h->halcmd.from_file);
    EXPECT_EQ(h->halcmd.file, "test.hal");
    EXPECT_FALSE(h->interactive);
}

TEST(HalrunOptions, InteractiveMustComeFirst)
{
    auto h = parse_halrun_options(V{"-I", "-f", "a.hal"});
    ASSERT_TRUE(h);
    EXPECT_TRUE(h->interactive);
    EXPECT_EQ(h->halcmd.file, "a.hal");
    auto bad = parse_halrun_options(V{"-f", "a.hal", "-I"});
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("-I must precede"), std::string::npos);
}

TEST(HalrunOptions, ForceExitMustBeAlone)
{
    auto h = parse_halrun_options(V{"-U"});
    ASSERT_TRUE(h);
    EXPECT_TRUE(h->force_exit);
    auto bad = parse_halrun_options(V{"-U", "-k"});
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("-U must be the only"), std::string::npos);
}

TEST(HalrunOptions, CommandIsPassedThrough)
{
    auto h = parse_halrun_options(V{"-k", "show", "pin"});
    ASSERT_TRUE(h);
    EXPECT_TRUE(h->halcmd.keep_going);
    EXPECT_EQ(h->halcmd.command, (V{"show", "pin"}));
}

TEST(HalcmdOptions, FlavorChoosesKernelOrSim)
{
    EXPECT_EQ(parse_ok({"--flavor=kernel", "show"}).flavor, "kernel");
    Options o = parse_ok({"--flavor", "sim", "-f", "x.hal"});
    EXPECT_EQ(o.flavor, "sim");
    EXPECT_EQ(o.file, "x.hal");
    EXPECT_EQ(parse_ok({"show"}).flavor, "");
    EXPECT_EQ(parse_err({"--flavor=rtai"}), "--flavor=rtai: must be kernel or sim (try 'halcmd -h')");
    EXPECT_EQ(parse_err({"--flavor"}), "option --flavor needs kernel or sim (try 'halcmd -h')");
}

TEST(HalrunOptions, FlavorBeforeOtherOptions)
{
    auto u = parse_halrun_options(V{"--flavor=kernel", "-U"});
    ASSERT_TRUE(u) << u.error().message;
    EXPECT_TRUE(u->force_exit);
    EXPECT_EQ(u->halcmd.flavor, "kernel");
    auto i = parse_halrun_options(V{"--flavor", "sim", "-I", "x.hal"});
    ASSERT_TRUE(i) << i.error().message;
    EXPECT_TRUE(i->interactive);
    EXPECT_EQ(i->halcmd.flavor, "sim");
    EXPECT_EQ(i->halcmd.file, "x.hal");
}
