// SPDX-License-Identifier: GPL-2.0-or-later
// options_test.cpp - the comp(1) command line.
#include <gtest/gtest.h>

#include <vector>

#include "options.hpp"

using namespace hal::comp;

namespace {

hal::Result<Options> parse(std::vector<std::string> args)
{
    static std::vector<std::string> keep;
    keep = args;
    keep.insert(keep.begin(), "comp");
    std::vector<char*> argv;
    for (auto& a : keep)
        argv.push_back(a.data());
    return parse_options(std::span(argv));
}

}  // namespace

TEST(CompOptions, DefaultsToPreprocess)
{
    auto o = parse({"x.comp"});
    ASSERT_TRUE(o.has_value());
    EXPECT_EQ(o->mode, Mode::Preprocess);
    EXPECT_EQ(o->files, std::vector<std::string>{"x.comp"});
}

TEST(CompOptions, ReadsModeUserspaceAndOutput)
{
    auto o = parse({"--compile", "--userspace", "-o", "out", "x.comp"});
    ASSERT_TRUE(o.has_value());
    EXPECT_EQ(o->mode, Mode::Compile);
    EXPECT_TRUE(o->userspace);
    EXPECT_EQ(o->output, "out");
}

TEST(CompOptions, RefusesConflictsAndUnknowns)
{
    EXPECT_EQ(parse({"--compile", "--document", "x.comp"}).error().message,
              "only one of --compile, --preprocess, --document, --view-doc, --install, "
              "--install-doc may be given (found --document)");
    EXPECT_EQ(parse({"--frob", "x.comp"}).error().message, "unknown option '--frob'");
    EXPECT_EQ(parse({}).error().message, "no input file (give a .comp, .c or .py file)");
    EXPECT_EQ(parse({"-o", "y", "a.comp", "b.comp"}).error().message, "-o needs exactly one input file");
    EXPECT_EQ(parse({"x.comp", "-o"}).error().message, "-o needs a file name");
    EXPECT_EQ(parse({"--personalities=0", "x.comp"}).error().message,
              "--personalities=0: give a number of personalities, 1..1024");
}

TEST(CompOptions, ExtraArgsAndPersonalities)
{
    auto o = parse({"--extra-compile-args=-DA=1", "--extra-compile-args", "-DB", "--extra-link-args=-lm",
                    "--personalities=8", "x.comp"});
    ASSERT_TRUE(o);
    EXPECT_EQ(o->extra_compile_args, "-DA=1 -DB");
    EXPECT_EQ(o->extra_link_args, "-lm");
    EXPECT_EQ(o->personalities, 8);
}
