// SPDX-License-Identifier: GPL-2.0-or-later
// hal_alloc_test.cpp - the segment heap (hal_alloc.c) on a private heap buffer:
// alignment, zeroing, owner tags, reclaiming by owner, merging, first fit.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include "hal_test_internal.h"

namespace {

constexpr rtapi_u32 kSegSize = 4u << 20;
constexpr rtapi_u32 kHdr = sizeof(struct hal_block_hdr);

// Bytes a request of 'size' really takes: header plus data, rounded to HAL_ALIGN.
constexpr rtapi_u32 block_bytes(rtapi_u32 size) { return (size + kHdr + HAL_ALIGN - 1) & ~(HAL_ALIGN - 1); }

class HalAlloc : public ::testing::Test {
protected:
    void SetUp() override
    {
        seg_ = static_cast<struct hal_seg_hdr*>(std::aligned_alloc(4096, kSegSize));
        ASSERT_NE(seg_, nullptr);
        std::memset(seg_, 0xa5, kSegSize);   // the heap must not rely on zeroed memory
        hal_segment_init(seg_, kSegSize);
    }
    void TearDown() override { std::free(seg_); }

    rtapi_u32 off(const void* p) const { return static_cast<rtapi_u32>(static_cast<const char*>(p) - base()); }
    const char* base() const { return reinterpret_cast<const char*>(seg_); }
    static struct hal_block_hdr* hdr(void* p) { return static_cast<struct hal_block_hdr*>(p) - 1; }
    void* alloc(rtapi_u32 size, rtapi_u32 owner = 0) { return hal_alloc_block(seg_, size, HAL_KIND_MALLOC, owner); }
    int free_blocks() const
    {
        int n = 0;
        for (rtapi_u32 o = seg_->free_head; o; o = reinterpret_cast<const hal_block_hdr*>(base() + o)->next_free_off)
            n++;
        return n;
    }

    struct hal_seg_hdr* seg_ = nullptr;
};

TEST_F(HalAlloc, StartsWithAnEmptyHeapAfterTheHashTable)
{
    EXPECT_EQ(seg_->magic, HAL_SEG_MAGIC);
    EXPECT_EQ(seg_->heap_top, seg_->heap_start);
    EXPECT_GE(seg_->heap_start, seg_->hash_off + HAL_HASH_BUCKETS * sizeof(rtapi_u32));
    EXPECT_EQ(seg_->bytes_used, 0u);
    EXPECT_EQ(seg_->free_head, 0u);
}

TEST_F(HalAlloc, ReturnsEightByteAlignedMemoryForOddSizes)
{
    for (rtapi_u32 size : {1u, 3u, 7u, 13u, 29u}) {
        void* p = alloc(size);
        ASSERT_NE(p, nullptr);
        EXPECT_EQ(off(p) % 8, 0u) << "size " << size;
    }
}

TEST_F(HalAlloc, ReturnsZeroedMemoryEvenWhenReusingADirtyBlock)
{
    auto* p = static_cast<unsigned char*>(alloc(40));
    ASSERT_NE(p, nullptr);
    for (int i = 0; i < 40; i++)
        EXPECT_EQ(p[i], 0) << i;
    std::memset(p, 0xff, 40);
    hal_free_block(seg_, p);
    auto* q = static_cast<unsigned char*>(alloc(40));
    ASSERT_EQ(q, p);
    for (int i = 0; i < 40; i++)
        EXPECT_EQ(q[i], 0) << i;
}

TEST_F(HalAlloc, TagsEachBlockWithItsKindAndOwner)
{
    void* p = hal_alloc_block(seg_, 24, HAL_KIND_STRING, 0x1234);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(hdr(p)->kind, HAL_KIND_STRING);
    EXPECT_EQ(hdr(p)->owner_off, 0x1234u);
    EXPECT_EQ(hdr(p)->size, block_bytes(24));
}

TEST_F(HalAlloc, CountsBytesUsedIncludingTheBlockHeader)
{
    alloc(1);
    alloc(100);
    EXPECT_EQ(seg_->bytes_used, block_bytes(1) + block_bytes(100));
    EXPECT_EQ(seg_->heap_top - seg_->heap_start, block_bytes(1) + block_bytes(100));
}

TEST_F(HalAlloc, FreeBlockGivesTheBytesBack)
{
    void* p = alloc(64);
    hal_free_block(seg_, p);
    EXPECT_EQ(seg_->bytes_used, 0u);
    EXPECT_EQ(hdr(p)->kind, HAL_KIND_FREE);
    EXPECT_EQ(seg_->free_head, off(hdr(p)));
}

TEST_F(HalAlloc, FirstFitReusesAFreedBlockBeforeGrowingTheHeap)
{
    void* a = alloc(64);
    alloc(64);
    rtapi_u32 top = seg_->heap_top;
    hal_free_block(seg_, a);
    EXPECT_EQ(alloc(64), a);
    EXPECT_EQ(seg_->heap_top, top);
}

TEST_F(HalAlloc, SplitsALargeFreeBlockAndReusesTheRest)
{
    char* big = static_cast<char*>(alloc(1024));
    alloc(8);   // keeps the freed block away from the heap top
    rtapi_u32 top = seg_->heap_top;
    hal_free_block(seg_, big);

    char* first = static_cast<char*>(alloc(64));
    char* second = static_cast<char*>(alloc(64));
    EXPECT_EQ(first, big);
    EXPECT_EQ(hdr(first)->size, block_bytes(64));
    EXPECT_EQ(second, big + block_bytes(64));
    EXPECT_EQ(seg_->heap_top, top);
}

TEST_F(HalAlloc, KeepsARemainderTooSmallToSplitInsideTheBlock)
{
    void* a = alloc(80);   // 96-byte block
    alloc(8);
    hal_free_block(seg_, a);
    rtapi_u32 used = seg_->bytes_used;
    void* b = alloc(48);   // needs 64: the 32 left over is below the split minimum
    ASSERT_EQ(b, a);
    EXPECT_EQ(hdr(b)->size, block_bytes(80));
    EXPECT_EQ(seg_->bytes_used, used + block_bytes(80));
    EXPECT_EQ(free_blocks(), 0);
}

TEST_F(HalAlloc, FreeOwnedReclaimsOnlyThatOwnersBlocks)
{
    void* a1 = alloc(32, 100);
    void* b = alloc(32, 200);
    void* a2 = alloc(48, 100);
    hal_free_owned(seg_, 100);
    EXPECT_EQ(hdr(a1)->kind, HAL_KIND_FREE);
    EXPECT_EQ(hdr(a2)->kind, HAL_KIND_FREE);
    EXPECT_EQ(hdr(b)->kind, HAL_KIND_MALLOC);
    EXPECT_EQ(hdr(b)->owner_off, 200u);
    EXPECT_EQ(seg_->bytes_used, block_bytes(32));
}

TEST_F(HalAlloc, FreeOwnedReturnsTheFreeTailToTheBumpArea)
{
    alloc(32, 100);
    alloc(32, 100);
    hal_free_owned(seg_, 100);
    EXPECT_EQ(seg_->heap_top, seg_->heap_start);
    EXPECT_EQ(seg_->free_head, 0u);
    EXPECT_EQ(seg_->bytes_used, 0u);
}

TEST_F(HalAlloc, FreeOwnedMergesNeighbouringFreeBlocks)
{
    char* x = static_cast<char*>(alloc(64, 1));
    alloc(64, 1);
    alloc(64, 2);   // stays: the merged block is not at the top
    rtapi_u32 top = seg_->heap_top;
    hal_free_owned(seg_, 1);
    ASSERT_EQ(free_blocks(), 1);
    EXPECT_EQ(hdr(x)->size, 2 * block_bytes(64));
    // A request that only fits the merged block lands there, not at the top.
    EXPECT_EQ(alloc(2 * block_bytes(64) - kHdr), x);
    EXPECT_EQ(seg_->heap_top, top);
}

TEST_F(HalAlloc, CompactMergesBlocksFreedOneByOne)
{
    void* a = alloc(16);
    void* b = alloc(16);
    void* c = alloc(16);
    alloc(16);
    hal_free_block(seg_, c);
    hal_free_block(seg_, a);
    hal_free_block(seg_, b);
    EXPECT_EQ(free_blocks(), 3);
    hal_heap_compact(seg_);
    EXPECT_EQ(free_blocks(), 1);
    EXPECT_EQ(seg_->free_head, off(hdr(a)));
    EXPECT_EQ(hdr(a)->size, 3 * block_bytes(16));
}

TEST_F(HalAlloc, CompactDropsAFreeTailFromTheFreeList)
{
    void* keep = alloc(16);
    void* mid = alloc(16);
    alloc(16);
    void* last = alloc(16);
    hal_free_block(seg_, mid);
    hal_free_block(seg_, last);
    hal_heap_compact(seg_);
    EXPECT_EQ(seg_->heap_top, off(hdr(last)));
    ASSERT_EQ(free_blocks(), 1);
    EXPECT_EQ(seg_->free_head, off(hdr(mid)));
    EXPECT_EQ(hdr(keep)->kind, HAL_KIND_MALLOC);
}

TEST_F(HalAlloc, RefusesAZeroSizedRequest)
{
    EXPECT_EQ(alloc(0), nullptr);
    EXPECT_EQ(seg_->heap_top, seg_->heap_start);
}

TEST_F(HalAlloc, RefusesARequestLargerThanTheSegment)
{
    EXPECT_EQ(alloc(kSegSize + 1), nullptr);
    EXPECT_EQ(alloc(0xfffffff0u), nullptr);
    EXPECT_EQ(seg_->bytes_used, 0u);
}

TEST_F(HalAlloc, ReturnsNullWhenTheSegmentIsFullAndChangesNothing)
{
    rtapi_u32 room = seg_->val_start - seg_->heap_top;
    void* all = alloc(room - kHdr);   // exactly fills the record heap
    ASSERT_NE(all, nullptr);
    EXPECT_EQ(seg_->heap_top, seg_->val_start);
    rtapi_u32 used = seg_->bytes_used;
    EXPECT_EQ(alloc(1), nullptr);
    EXPECT_EQ(seg_->bytes_used, used);
    EXPECT_EQ(seg_->heap_top, seg_->val_start);
}

TEST_F(HalAlloc, SpaceFreedByAnOwnerCanBeAllocatedAgainWhenFull)
{
    rtapi_u32 room = seg_->val_start - seg_->heap_top;
    alloc(room / 2, 7);
    alloc(room / 2 - 64, 8);
    EXPECT_EQ(alloc(room / 2, 9), nullptr);
    hal_free_owned(seg_, 7);
    EXPECT_NE(alloc(room / 4, 9), nullptr);
}

}  // namespace

// The value area (signal values, dummies, userspace components' memory) has no block
// headers: a bitmap in the record heap hands out its granules, so users who may write
// the value area cannot forge allocator metadata.
TEST_F(HalAlloc, ValueBlocksComeFromTheValueAreaWithoutHeadersThere)
{
    void* rec = alloc(40);
    void* val = hal_alloc_block(seg_, 8, HAL_KIND_VALUE, 3);
    void* mem = hal_alloc_block(seg_, 60, HAL_KIND_UMALLOC, 3);
    ASSERT_NE(val, nullptr);
    ASSERT_NE(mem, nullptr);
    EXPECT_LT(off(rec), seg_->val_start);
    EXPECT_GE(off(val), seg_->val_start);
    EXPECT_EQ(off(mem), off(val) + 8);   // back to back: nothing between them
    EXPECT_EQ(seg_->val_start % 4096, 0u);
    EXPECT_EQ(seg_->val_bytes_used, 8u + 64u);
    EXPECT_LT(seg_->val_map_off, seg_->heap_start);
    std::memset(mem, 0xff, 64);          // a user scribbling over it changes nothing below
    hal_free_owned(seg_, 3);             // the hal_malloc memory goes with its owner
    hal_free_block(seg_, val);
    EXPECT_EQ(seg_->val_bytes_used, 0u);
    void* again = hal_alloc_block(seg_, 16, HAL_KIND_VALUE, 0);
    EXPECT_EQ(off(again), off(val));     // first fit reuses the freed granules
}

TEST_F(HalAlloc, ValueAreaRefusesWhenFullAndFindsFreedRuns)
{
    rtapi_u32 total = seg_->size - seg_->val_start;
    void* all = hal_alloc_block(seg_, total, HAL_KIND_VALUE, 0);
    ASSERT_NE(all, nullptr);
    EXPECT_EQ(hal_alloc_block(seg_, 8, HAL_KIND_VALUE, 0), nullptr);
}

// hal_umalloc_owned() is how the core checks an offset a user sent: the whole range
// must be inside hal_malloc() memory of that very component.
TEST_F(HalAlloc, UmallocOwnedAcceptsOnlyWholeRangesOfTheOwnersMemory)
{
    char* mem = static_cast<char*>(hal_alloc_block(seg_, 64, HAL_KIND_UMALLOC, 9));
    char* other = static_cast<char*>(hal_alloc_block(seg_, 64, HAL_KIND_UMALLOC, 10));
    ASSERT_NE(mem, nullptr);
    EXPECT_TRUE(hal_umalloc_owned(seg_, 9, off(mem), 8));
    EXPECT_TRUE(hal_umalloc_owned(seg_, 9, off(mem) + 56, 8));
    EXPECT_FALSE(hal_umalloc_owned(seg_, 9, off(mem) + 60, 8));    // runs past it
    EXPECT_FALSE(hal_umalloc_owned(seg_, 9, off(other), 8));       // another owner's
    EXPECT_FALSE(hal_umalloc_owned(seg_, 9, seg_->heap_start, 8)); // the records
    EXPECT_FALSE(hal_umalloc_owned(seg_, 9, 0xfffffff0u, 8));
    EXPECT_FALSE(hal_umalloc_owned(seg_, 9, off(mem), 0xffffffffu));
    hal_free_owned(seg_, 9);
    EXPECT_FALSE(hal_umalloc_owned(seg_, 9, off(mem), 8));
}
