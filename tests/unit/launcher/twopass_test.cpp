// SPDX-License-Identifier: GPL-2.0-or-later
// [HAL]TWOPASS splitting: load lines first (count=/names= merged), the rest after,
// line numbers kept.
#include <gtest/gtest.h>

#include "twopass.hpp"

using namespace hal::launcher;

TEST(TwoPass, LoadsFirstAndMerged)
{
    auto r = twopass_split({{"a.hal", "loadrt threads name1=t period1=1000\nloadrt and2 count=1\naddf and2.1 t\n"},
                            {"b.hal", "# c\nloadrt and2 count=2\nloadrt not names=x\nloadrt not names=y,z\n"
                                      "loadusr -W prog\nnet s and2.0.out x.in\n"}});
    ASSERT_TRUE(r);
    ASSERT_EQ(r->pass0.size(), 4u);
    EXPECT_EQ(r->pass0[0].line, "loadrt threads name1=t period1=1000");
    EXPECT_EQ(r->pass0[1].line, "loadrt and2 count=3");
    EXPECT_EQ(r->pass0[1].where, "a.hal:2");
    EXPECT_EQ(r->pass0[2].line, "loadrt not names=x,y,z");
    EXPECT_EQ(r->pass0[3].line, "loadusr -W prog");
    EXPECT_EQ(r->pass0[3].where, "b.hal:5");
    ASSERT_EQ(r->pass1.size(), 2u);
    EXPECT_EQ(r->pass1[0].pass1_text, "\n\naddf and2.1 t\n");
    EXPECT_EQ(r->pass1[1].pass1_text, "# c\n\n\n\n\nnet s and2.0.out x.in\n");
}

TEST(TwoPass, DifferentParametersAreNotMerged)
{
    auto r = twopass_split({{"a.hal", "loadrt pid count=1 debug=1\nloadrt pid count=1\n"}});
    ASSERT_TRUE(r);
    ASSERT_EQ(r->pass0.size(), 2u);   // loading pid twice fails later, as it would anyway
}

TEST(TwoPass, ContinuationLinesAndComments)
{
    auto r = twopass_split({{"a.hal", "loadrt and2 \\\n count=2 # two\nsetp x 1\n"}});
    ASSERT_TRUE(r);
    ASSERT_EQ(r->pass0.size(), 1u);
    EXPECT_EQ(r->pass0[0].line, "loadrt and2 count=2");
    EXPECT_EQ(r->pass1[0].pass1_text, "\n\nsetp x 1\n");
}

TEST(TwoPass, BadCountIsAnError)
{
    auto r = twopass_split({{"a.hal", "\nloadrt and2 count=x\n"}});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "a.hal:2: bad count=x");
}
