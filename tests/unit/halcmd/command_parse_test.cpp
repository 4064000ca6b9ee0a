// SPDX-License-Identifier: GPL-2.0-or-later
// command_parse_test.cpp - parse_command(): a line's words against the dispatch table
// (setp shorthand, arrows of net/link*, argument counts) before any handler runs.
#include <gtest/gtest.h>

#include "commands.hpp"

using namespace hal::halcmd;
using V = std::vector<std::string>;

TEST(ParseCommand, NoWordsIsNoCommand)
{
    auto p = parse_command({});
    ASSERT_TRUE(p.has_value());
    EXPECT_EQ(p->command, nullptr);
}

TEST(ParseCommand, AssignmentIsSetp)
{
    auto p = parse_command({"and2.0.in0", "=", "1"});
    ASSERT_TRUE(p.has_value());
    EXPECT_STREQ(p->command->name, "setp");
    EXPECT_EQ(p->args, (V{"and2.0.in0", "1"}));
}

TEST(ParseCommand, NetDropsArrowsSetpKeepsThem)
{
    auto p = parse_command({"net", "s", "a.out", "=>", "b.in", "<=>", "c.io"});
    ASSERT_TRUE(p.has_value());
    EXPECT_EQ(p->args, (V{"s", "a.out", "b.in", "c.io"}));
    auto q = parse_command({"echo", "=>", "x"});
    ASSERT_TRUE(q.has_value());
    EXPECT_EQ(q->args, (V{"=>", "x"}));
}

TEST(ParseCommand, UnknownCommandAndWrongCountAreErrors)
{
    auto p = parse_command({"frobnicate", "x"});
    ASSERT_FALSE(p.has_value());
    EXPECT_EQ(p.error().message, "unknown command 'frobnicate' (try 'help')");
    auto q = parse_command({"newsig", "s"});
    ASSERT_FALSE(q.has_value());
    EXPECT_EQ(q.error().message, "newsig: wrong number of arguments (usage: newsig SIGNAME TYPE)");
    // Arrows do not count as arguments: "linkps p =>" has one.
    auto r = parse_command({"linkps", "p", "=>"});
    ASSERT_FALSE(r.has_value());
}
