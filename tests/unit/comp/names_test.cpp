// SPDX-License-Identifier: GPL-2.0-or-later
// names_test.cpp - .comp names to HAL names and C names (LANGUAGE.md "Names").
#include <gtest/gtest.h>

#include "names.hpp"

using namespace hal::comp;

TEST(CompNames, HalNamesUseDashesAndDropTrailingSeparators)
{
    EXPECT_EQ(to_hal("conv_bit_s32"), "conv-bit-s32");
    EXPECT_EQ(to_hal("in_"), "in");
    EXPECT_EQ(to_hal("out-of-range"), "out-of-range");
    EXPECT_EQ(to_hal("update_freq"), "update-freq");
}

TEST(CompNames, ArrayNamesBecomeZeroPaddedFormats)
{
    EXPECT_EQ(to_hal_format("out-#"), "out-%01d");
    EXPECT_EQ(to_hal_format("in-##"), "in-%02d");
    EXPECT_EQ(to_hal_format("x_val.#"), "x-val.%01d");
}

TEST(CompNames, CNamesDropIndexBlocksAndUseUnderscores)
{
    EXPECT_EQ(to_c("out-#"), "out");
    EXPECT_EQ(to_c("in-##"), "in");
    EXPECT_EQ(to_c("min-val"), "min_val");
    EXPECT_EQ(to_c("a.b-c"), "a_b_c");
    EXPECT_EQ(to_c("in_"), "in_");
    EXPECT_EQ(to_c("a--b"), "a_b");
}

TEST(CompNames, CountsHashBlocks)
{
    EXPECT_EQ(hash_blocks("out"), 0);
    EXPECT_EQ(hash_blocks("out-##"), 1);
    EXPECT_EQ(hash_blocks("a-#-#"), 2);
}

TEST(CompNames, QuotesCStrings)
{
    EXPECT_EQ(c_quote("a \"b\"\\\n"), "\"a \\\"b\\\"\\\\\\n\"");
}
