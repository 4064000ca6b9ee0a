// SPDX-License-Identifier: GPL-2.0-or-later
// module_args_test.cpp - insmod-style module arguments: both input forms, quotes,
// duplicates, every error message, and the joined form read back unchanged.
#include "module_args.hpp"

#include <gtest/gtest.h>

#include <cerrno>

namespace {

using hal::ModuleArg;
using Args = std::vector<ModuleArg>;

Args parse_items(const std::vector<std::string>& items)
{
    auto r = hal::parse_module_args("mod", items);
    EXPECT_TRUE(r) << (r ? "" : r.error().message);
    return r ? *r : Args{};
}

Args parse_joined(std::string_view joined)
{
    auto r = hal::parse_module_args("mod", joined);
    EXPECT_TRUE(r) << (r ? "" : r.error().message);
    return r ? *r : Args{};
}

std::string items_error(const std::vector<std::string>& items)
{
    auto r = hal::parse_module_args("mod", items);
    EXPECT_FALSE(r);
    if (r)
        return "";
    EXPECT_EQ(r.error().code, -EINVAL);
    return r.error().message;
}

std::string joined_error(std::string_view joined)
{
    auto r = hal::parse_module_args("mod", joined);
    EXPECT_FALSE(r);
    if (r)
        return "";
    EXPECT_EQ(r.error().code, -EINVAL);
    return r.error().message;
}

TEST(ModuleArgsItems, ParsesNameValuePairsInOrder)
{
    EXPECT_EQ(parse_items({"count=3", "names=a,b"}),
              (Args{{"count", "3"}, {"names", "a,b"}}));
}

TEST(ModuleArgsItems, AcceptsNoArguments)
{
    EXPECT_TRUE(parse_items({}).empty());
}

TEST(ModuleArgsItems, SplitsAtTheFirstEqualsSign)
{
    EXPECT_EQ(parse_items({"cfg=a=b"}), (Args{{"cfg", "a=b"}}));
}

TEST(ModuleArgsItems, AcceptsAnEmptyValue)
{
    EXPECT_EQ(parse_items({"label="}), (Args{{"label", ""}}));
}

TEST(ModuleArgsItems, StripsOnePairOfDoubleOrSingleQuotes)
{
    EXPECT_EQ(parse_items({"a=\"x y\"", "b='p,q'", "c=\"\""}),
              (Args{{"a", "x y"}, {"b", "p,q"}, {"c", ""}}));
}

TEST(ModuleArgsItems, KeepsSpacesAndUnpairedQuotes)
{
    EXPECT_EQ(parse_items({"a=x y", "b=\"x'", "c=it's"}),
              (Args{{"a", "x y"}, {"b", "\"x'"}, {"c", "it's"}}));
}

TEST(ModuleArgsItems, LastOfADuplicateWinsAtTheFirstPosition)
{
    EXPECT_EQ(parse_items({"count=1", "fp=0", "count=2"}),
              (Args{{"count", "2"}, {"fp", "0"}}));
}

TEST(ModuleArgsItems, RefusesANameWithoutValue)
{
    EXPECT_EQ(items_error({"count=1", "debug"}),
              "mod: parameter 'debug' has no value (use debug=VALUE)");
}

TEST(ModuleArgsItems, RefusesAValueWithoutName)
{
    EXPECT_EQ(items_error({"=5"}), "mod: argument '=5' has no parameter name");
}

TEST(ModuleArgsItems, RefusesAnEmptyArgument)
{
    EXPECT_EQ(items_error({""}), "mod: empty argument");
}

TEST(ModuleArgsItems, RefusesANameNoModuleCanDeclare)
{
    EXPECT_EQ(items_error({"step-type=1"}), "mod: unknown parameter 'step-type'");
    EXPECT_EQ(items_error({"1x=1"}), "mod: unknown parameter '1x'");
}

TEST(ModuleArgsJoined, SplitsAtBlanksAndTabs)
{
    EXPECT_EQ(parse_joined("  count=3\tnames=a,b  "),
              (Args{{"count", "3"}, {"names", "a,b"}}));
}

TEST(ModuleArgsJoined, AcceptsAnEmptyLine)
{
    EXPECT_TRUE(parse_joined("").empty());
    EXPECT_TRUE(parse_joined("  \t ").empty());
}

TEST(ModuleArgsJoined, KeepsBlanksInsideQuotesAndRemovesTheQuotes)
{
    EXPECT_EQ(parse_joined("names=\"a b\" label='x  y' c=\"\""),
              (Args{{"names", "a b"}, {"label", "x  y"}, {"c", ""}}));
}

TEST(ModuleArgsJoined, RemovesQuotesAnywhereInAnItem)
{
    EXPECT_EQ(parse_joined("\"count=3\" a=x\"y z\"w"), (Args{{"count", "3"}, {"a", "xy zw"}}));
}

TEST(ModuleArgsJoined, KeepsTheOtherQuoteInsideQuotes)
{
    EXPECT_EQ(parse_joined("a=\"it's\" b='say \"hi\"'"),
              (Args{{"a", "it's"}, {"b", "say \"hi\""}}));
}

TEST(ModuleArgsJoined, TheFirstEqualsSignEndsTheNameEvenInsideQuotes)
{
    EXPECT_EQ(parse_joined("cfg=\"x=1\" \"a=b\""), (Args{{"cfg", "x=1"}, {"a", "b"}}));
}

TEST(ModuleArgsJoined, LastOfADuplicateWins)
{
    EXPECT_EQ(parse_joined("count=1 count=4"), (Args{{"count", "4"}}));
}

TEST(ModuleArgsJoined, RefusesAnUnterminatedQuote)
{
    EXPECT_EQ(joined_error("count=1 names=\"a b"), "mod: unterminated quote in 'names=\"a b'");
}

TEST(ModuleArgsJoined, RefusesANameWithoutValue)
{
    EXPECT_EQ(joined_error("count=1 debug"),
              "mod: parameter 'debug' has no value (use debug=VALUE)");
}

TEST(ModuleArgsJoined, RefusesAValueWithoutName)
{
    EXPECT_EQ(joined_error("=5"), "mod: argument '=5' has no parameter name");
}

TEST(ModuleArgsJoined, RefusesAnEmptyQuotedArgument)
{
    EXPECT_EQ(joined_error("\"\""), "mod: empty argument");
}

TEST(ModuleArgsCheck, AcceptsDeclaredNames)
{
    EXPECT_TRUE(hal::check_module_args("pid", {{"num_chan", "2"}}, {"num_chan", "debug"}));
    EXPECT_TRUE(hal::check_module_args("pid", {}, {}));
}

TEST(ModuleArgsCheck, RefusesAnUndeclaredName)
{
    auto r = hal::check_module_args("pid", {{"num_chan", "2"}, {"foo", "1"}}, {"num_chan"});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, -EINVAL);
    EXPECT_EQ(r.error().message, "pid: unknown parameter 'foo'");
}

TEST(ModuleArgsJoin, WritesPlainValuesAsTheyAre)
{
    auto r = hal::join_module_args("mod", {{"count", "3"}, {"names", "a,b"}, {"e", ""}});
    ASSERT_TRUE(r);
    EXPECT_EQ(*r, "count=3 names=a,b e=");
}

TEST(ModuleArgsJoin, QuotesValuesSoTheyReadBackUnchanged)
{
    Args args{{"a", "x y"}, {"b", "it's"}, {"c", "say \"hi\""}, {"d", "tab\there"}};
    auto joined = hal::join_module_args("mod", args);
    ASSERT_TRUE(joined);
    EXPECT_EQ(*joined, "a=\"x y\" b=\"it's\" c='say \"hi\"' d=\"tab\there\"");
    EXPECT_EQ(parse_joined(*joined), args);
}

TEST(ModuleArgsJoin, RefusesValuesNoQuotingCanCarry)
{
    auto both = hal::join_module_args("mod", {{"a", "it's \"x\""}});
    ASSERT_FALSE(both);
    EXPECT_EQ(both.error().message, "mod: value of parameter 'a' contains both kinds of quote");
    auto newline = hal::join_module_args("mod", {{"a", "x\ny"}});
    ASSERT_FALSE(newline);
    EXPECT_EQ(newline.error().message, "mod: value of parameter 'a' contains a line break or NUL");
    auto nul = hal::join_module_args("mod", {{"a", std::string("x\0y", 3)}});
    EXPECT_FALSE(nul);
}

TEST(ModuleName, AcceptsLowercaseDigitsAndUnderscore)
{
    EXPECT_TRUE(hal::is_module_name("hm2_7i43"));
    EXPECT_TRUE(hal::is_module_name(std::string(31, 'a')));
}

TEST(ModuleName, RefusesAnythingThatCouldLeaveTheModuleDirectory)
{
    for (const char* bad : {"", "../pid", "pid.so", "Pid", "a b", "a/b", "a-b"})
        EXPECT_FALSE(hal::is_module_name(bad)) << bad;
    EXPECT_FALSE(hal::is_module_name(std::string(32, 'a')));
}

}  // namespace
