// SPDX-License-Identifier: GPL-2.0-or-later
// The sampler/streamer FIFO layout and index math (kernel/components/streamer_fifo.h).
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "streamer_fifo.h"

namespace {

// A FIFO in ordinary memory: header plus record area, as the two segments hold them.
struct TestFifo {
    hal_fifo_hdr hdr{};
    std::vector<hal_fifo_value> data;

    TestFifo(const char* cfg, rtapi_u32 depth)
    {
        int pins = hal_fifo_cfg_pins(cfg);
        hal_fifo_hdr_init(&hdr, cfg, pins, depth);
        data.resize(hdr.data_size / sizeof(hal_fifo_value));
        hal_fifo_publish(&hdr);
    }
    bool put(rtapi_u64 v)
    {
        hal_fifo_value* rec = hal_fifo_write_slot(&hdr, data.data());
        if (!rec)
            return false;
        rec[HAL_FIFO_REC_HDR_WORDS].u = v;
        hal_fifo_write_done(&hdr);
        return true;
    }
    bool get(rtapi_u64& v)
    {
        const hal_fifo_value* rec = hal_fifo_read_slot(&hdr, data.data());
        if (!rec)
            return false;
        v = rec[HAL_FIFO_REC_HDR_WORDS].u;
        hal_fifo_read_done(&hdr);
        return true;
    }
};

TEST(StreamerFifo, TypeCharactersAreCaseInsensitive)
{
    EXPECT_EQ(hal_fifo_type_of('f'), HAL_FIFO_FLOAT);
    EXPECT_EQ(hal_fifo_type_of('F'), HAL_FIFO_FLOAT);
    EXPECT_EQ(hal_fifo_type_of('B'), HAL_FIFO_BIT);
    EXPECT_EQ(hal_fifo_type_of('s'), HAL_FIFO_S32);
    EXPECT_EQ(hal_fifo_type_of('U'), HAL_FIFO_U32);
    EXPECT_EQ(hal_fifo_type_of('l'), HAL_FIFO_S64);
    EXPECT_EQ(hal_fifo_type_of('K'), HAL_FIFO_U64);
    EXPECT_EQ(hal_fifo_type_of('x'), HAL_FIFO_BAD);
}

TEST(StreamerFifo, CfgPinsCountsGoodStrings)
{
    EXPECT_EQ(hal_fifo_cfg_pins("ffbs"), 4);
    EXPECT_EQ(hal_fifo_cfg_pins("u"), 1);
    EXPECT_EQ(hal_fifo_cfg_pins("ffffffffffffffffffff"), HAL_FIFO_MAX_PINS);
}

TEST(StreamerFifo, CfgPinsPointsAtTheFirstBadCharacter)
{
    EXPECT_EQ(hal_fifo_cfg_pins(""), 0);
    EXPECT_EQ(hal_fifo_cfg_pins("ffx"), -3);
    EXPECT_EQ(hal_fifo_cfg_pins("fffffffffffffffffffff"), -(1 + HAL_FIFO_MAX_PINS));
}

TEST(StreamerFifo, DataSizeHasHeaderWordsAndOneSpareSlot)
{
    EXPECT_EQ(hal_fifo_data_size(10, 3), 11u * (2 + 3) * 8);
    EXPECT_EQ(hal_fifo_rec_words(4), 6u);
}

TEST(StreamerFifo, NextWrapsAtSlots)
{
    EXPECT_EQ(hal_fifo_next(0, 5), 1u);
    EXPECT_EQ(hal_fifo_next(4, 5), 0u);
}

TEST(StreamerFifo, CountHandlesWrappedIndices)
{
    EXPECT_EQ(hal_fifo_count(3, 3, 11), 0u);
    EXPECT_EQ(hal_fifo_count(7, 2, 11), 5u);
    EXPECT_EQ(hal_fifo_count(1, 9, 11), 3u);
    EXPECT_EQ(hal_fifo_count(9, 10, 11), 10u);
}

TEST(StreamerFifo, InitWritesGeometryAndKeepsMagicClear)
{
    hal_fifo_hdr h;
    std::memset(&h, 0x5a, sizeof(h));
    hal_fifo_hdr_init(&h, "fbsu", 4, 100);
    EXPECT_FALSE(hal_fifo_is_published(&h));
    EXPECT_EQ(h.depth, 100u);
    EXPECT_EQ(h.slots, 101u);
    EXPECT_EQ(h.num_pins, 4u);
    EXPECT_STREQ(h.cfg, "fbsu");
    EXPECT_EQ(h.in, 0u);
    EXPECT_EQ(h.out, 0u);
    EXPECT_TRUE(hal_fifo_geometry_ok(&h));
    hal_fifo_publish(&h);
    EXPECT_TRUE(hal_fifo_is_published(&h));
    hal_fifo_withdraw(&h);
    EXPECT_FALSE(hal_fifo_is_published(&h));
}

TEST(StreamerFifo, GeometryCheckRejectsInconsistentHeaders)
{
    hal_fifo_hdr h;
    hal_fifo_hdr_init(&h, "ff", 2, 10);
    h.num_pins = 3;
    EXPECT_FALSE(hal_fifo_geometry_ok(&h));
    hal_fifo_hdr_init(&h, "ff", 2, 10);
    h.slots = 10;
    EXPECT_FALSE(hal_fifo_geometry_ok(&h));
    hal_fifo_hdr_init(&h, "ff", 2, 10);
    h.cfg[1] = 'q';
    EXPECT_FALSE(hal_fifo_geometry_ok(&h));
}

TEST(StreamerFifo, HoldsExactlyDepthRecords)
{
    TestFifo f("u", 3);
    EXPECT_TRUE(f.put(1));
    EXPECT_TRUE(f.put(2));
    EXPECT_TRUE(f.put(3));
    EXPECT_EQ(hal_fifo_used(&f.hdr), 3u);
    EXPECT_FALSE(f.put(4));
    rtapi_u64 v = 0;
    EXPECT_TRUE(f.get(v));
    EXPECT_EQ(v, 1u);
    EXPECT_TRUE(f.put(4));
    EXPECT_FALSE(f.put(5));
}

TEST(StreamerFifo, EmptyFifoHasNothingToRead)
{
    TestFifo f("b", 2);
    rtapi_u64 v = 0;
    EXPECT_FALSE(f.get(v));
    EXPECT_EQ(hal_fifo_used(&f.hdr), 0u);
}

TEST(StreamerFifo, KeepsOrderAcrossManyWraps)
{
    TestFifo f("s", 4);
    rtapi_u64 next_in = 0, next_out = 0, v = 0;
    for (int round = 0; round < 100; round++) {
        while (f.put(next_in))
            next_in++;
        for (int k = 0; k < 1 + round % 4 && f.get(v); k++)
            EXPECT_EQ(v, next_out++);
    }
    while (f.get(v))
        EXPECT_EQ(v, next_out++);
    EXPECT_EQ(next_in, next_out);
}

TEST(StreamerFifo, RecordsDoNotOverlap)
{
    TestFifo f("ffff", 2);
    hal_fifo_value* r0 = hal_fifo_record(&f.hdr, f.data.data(), 0);
    hal_fifo_value* r2 = hal_fifo_record(&f.hdr, f.data.data(), 2);
    EXPECT_EQ(r0 + 6, hal_fifo_record(&f.hdr, f.data.data(), 1));
    EXPECT_EQ(r2 + 6, f.data.data() + f.data.size());
}

TEST(StreamerFifo, CorruptIndicesNeverReachOutsideTheRecords)
{
    TestFifo f("f", 4);
    f.hdr.in = 99;
    EXPECT_EQ(hal_fifo_write_slot(&f.hdr, f.data.data()), nullptr);
    EXPECT_EQ(hal_fifo_read_slot(&f.hdr, f.data.data()), nullptr);
    EXPECT_EQ(hal_fifo_used(&f.hdr), 0u);
    f.hdr.in = 0;
    f.hdr.out = 77;
    EXPECT_EQ(hal_fifo_read_slot(&f.hdr, f.data.data()), nullptr);
}

}  // namespace
