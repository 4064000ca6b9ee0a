// SPDX-License-Identifier: GPL-2.0-or-later
// mux_generic(9) config entries and selection with debounce (kernel/components/mux_generic_core.h).
#include <gtest/gtest.h>

#include "mux_generic_core.h"

namespace {

TEST(MuxGeneric, ParsesTypesInAnyCaseAndTheSize)
{
    mux_gen_cfg c{};
    ASSERT_EQ(mux_gen_parse("fU12", &c), 0);
    EXPECT_EQ(c.in_type, MUX_GEN_FLOAT);
    EXPECT_EQ(c.out_type, MUX_GEN_U32);
    EXPECT_EQ(c.size, 12);
    ASSERT_EQ(mux_gen_parse("Sb1024", &c), 0);
    EXPECT_EQ(c.size, 1024);
}

TEST(MuxGeneric, RefusesBadLettersAndSizes)
{
    mux_gen_cfg c{};
    EXPECT_EQ(mux_gen_parse("xb4", &c), -1);
    EXPECT_EQ(mux_gen_parse("b", &c), -1);
    EXPECT_EQ(mux_gen_parse("bb", &c), -2);
    EXPECT_EQ(mux_gen_parse("bb0", &c), -2);
    EXPECT_EQ(mux_gen_parse("bb1025", &c), -2);
    EXPECT_EQ(mux_gen_parse("bb4x", &c), -2);
    EXPECT_EQ(mux_gen_parse("bb99999999999", &c), -2);
}

TEST(MuxGeneric, SelBitsOnlyForPowersOfTwo)
{
    EXPECT_EQ(mux_gen_sel_bits(1), 0);
    EXPECT_EQ(mux_gen_sel_bits(2), 1);
    EXPECT_EQ(mux_gen_sel_bits(8), 3);
    EXPECT_EQ(mux_gen_sel_bits(1024), 10);
    EXPECT_EQ(mux_gen_sel_bits(12), 0);
}

TEST(MuxGeneric, NewSelectionWaitsOutTheDebounceTime)
{
    mux_gen_sel_state s{};
    EXPECT_TRUE(mux_gen_select(&s, 2, false, 3000, 1000000, 4));
    EXPECT_EQ(s.selected, 0);
    mux_gen_select(&s, 2, false, 3000, 1000000, 4);
    mux_gen_select(&s, 2, false, 3000, 1000000, 4);
    EXPECT_EQ(s.selected, 0);
    mux_gen_select(&s, 2, false, 3000, 1000000, 4);
    EXPECT_EQ(s.selected, 2);
}

TEST(MuxGeneric, SuppressAndOutOfRangeKeepTheOutput)
{
    mux_gen_sel_state s{};
    EXPECT_FALSE(mux_gen_select(&s, 0, true, 0, 1000000, 4));
    EXPECT_FALSE(mux_gen_select(&s, 4, false, 0, 1000000, 4));
    EXPECT_TRUE(mux_gen_select(&s, 3, false, 0, 1000000, 4));
    EXPECT_EQ(s.selected, 3);
}

}  // namespace
