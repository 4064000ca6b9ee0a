// SPDX-License-Identifier: GPL-2.0-or-later
// hal_size_test.cpp - HAL_SIZE, the size a new HAL segment gets (hal_segment.c):
// bytes or K/M/G, whole pages, the default when unset, refused outside 64M..1G.
#include <gtest/gtest.h>

#include <cerrno>
#include <cstdlib>

#include "hal_test_internal.h"

namespace {

// The size HAL_SIZE=text asks for, or the error.
int wanted(const char* text, rtapi_u32* size)
{
    if (text)
        setenv("HAL_SIZE", text, 1);
    else
        unsetenv("HAL_SIZE");
    int rc = hal_segment_size_wanted(size);
    unsetenv("HAL_SIZE");
    return rc;
}

TEST(HalSize, UnsetOrEmptyIsTheDefault)
{
    rtapi_u32 size = 0;
    ASSERT_EQ(wanted(nullptr, &size), 0);
    EXPECT_EQ(size, HAL_SEGMENT_SIZE_DEFAULT);
    size = 0;
    ASSERT_EQ(wanted("", &size), 0);
    EXPECT_EQ(size, HAL_SEGMENT_SIZE_DEFAULT);
}

TEST(HalSize, SuffixesAndBytes)
{
    rtapi_u32 size = 0;
    ASSERT_EQ(wanted("128M", &size), 0);
    EXPECT_EQ(size, 128u << 20);
    ASSERT_EQ(wanted("98304k", &size), 0);
    EXPECT_EQ(size, 96u << 20);
    ASSERT_EQ(wanted("1G", &size), 0);
    EXPECT_EQ(size, 1u << 30);
    ASSERT_EQ(wanted("67108864", &size), 0);
    EXPECT_EQ(size, 64u << 20);
}

TEST(HalSize, RoundedDownToWholePages)
{
    rtapi_u32 size = 0;
    ASSERT_EQ(wanted("80000001", &size), 0);
    EXPECT_EQ(size, 80000001u & ~4095u);
}

TEST(HalSize, OutOfRangeOrNotANumberIsRefused)
{
    for (const char* bad : {"63M", "16M", "2G", "1025M", "0", "abc", "64Q", "64MB", "-64M", " 64M",
                            "99999999999999999999999", "M"}) {
        rtapi_u32 size = 12345;
        EXPECT_EQ(wanted(bad, &size), -EINVAL) << bad;
        EXPECT_EQ(size, 12345u) << bad;
    }
}

}  // namespace
