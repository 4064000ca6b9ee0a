// SPDX-License-Identifier: GPL-2.0-or-later
// hal_request_test.cpp - the checks of hal_req_execute() (hal_request.c), which the
// kernel flavor runs for a possibly hostile user: unterminated names, unknown
// operations, offsets outside the caller's own userspace-component memory, other
// processes' components, bad lock levels, typed writes. On a private segment.
#include <gtest/gtest.h>
#include <gmock/gmock.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>

#include "hal_test_internal.h"
#include "msg_capture.hpp"

namespace {

using ::testing::HasSubstr;

constexpr rtapi_u32 kSegSize = 4u << 20;

class HalRequest : public ::testing::Test {
protected:
    void SetUp() override
    {
        buf_ = static_cast<char*>(std::aligned_alloc(4096, kSegSize));
        ASSERT_NE(buf_, nullptr);
        std::memset(buf_, 0, kSegSize);
        hal_segment_init(reinterpret_cast<struct hal_seg_hdr*>(buf_), kSegSize);
        hal_shmem_base = buf_;
        hal_seg = reinterpret_cast<struct hal_seg_hdr*>(buf_);
    }
    void TearDown() override
    {
        hal_shmem_base = nullptr;
        hal_seg = nullptr;
        std::free(buf_);
    }
    static struct hal_req req(enum hal_req_op op, const char* name = "", const char* name2 = "")
    {
        struct hal_req r;
        std::memset(&r, 0, sizeof(r));
        r.op = op;
        std::strncpy(r.name, name, sizeof(r.name) - 1);
        std::strncpy(r.name2, name2, sizeof(r.name2) - 1);
        return r;
    }
    int run(struct hal_req& r, int pid = 100) const
    {
        struct hal_caller c = { true, pid };
        return hal_req_execute(&r, &c);
    }
    // A userspace component of 'pid' with 'bytes' of hal_malloc memory; returns the id.
    int comp(const char* name, int pid, rtapi_u32* mem_off, rtapi_u32 bytes = 64)
    {
        struct hal_req r = req(HAL_REQ_COMP_NEW, name);
        r.value = 0x7f0000000000ull;   // where that process maps the segment
        int id = run(r, pid);
        EXPECT_GT(id, 0);
        struct hal_req m = req(HAL_REQ_MALLOC);
        m.comp_id = id;
        m.value = bytes;
        EXPECT_EQ(run(m, pid), 0);
        *mem_off = m.off;
        return id;
    }
    int pin(int comp_id, rtapi_u32 off, int pid = 100, const char* name = "u.p")
    {
        struct hal_req r = req(HAL_REQ_PIN_NEW, name);
        r.type = HAL_FLOAT;
        r.dir = HAL_IN;
        r.comp_id = comp_id;
        r.off = off;
        return run(r, pid);
    }
    char* buf_ = nullptr;
};

TEST_F(HalRequest, RefusesANameThatFillsItsField)
{
    struct hal_req r = req(HAL_REQ_SIG_NEW);
    std::memset(r.name, 'a', sizeof(r.name));   // no terminating NUL
    hal_test::MsgCapture msgs;
    EXPECT_EQ(run(r), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("name is not a string of at most 63 characters"));
    EXPECT_EQ(hal_seg->count[HAL_KIND_SIG], 0u);
}

TEST_F(HalRequest, RefusesUnknownOperations)
{
    hal_test::MsgCapture msgs;
    for (rtapi_u32 op : {0u, static_cast<rtapi_u32>(HAL_REQ_OP_END), 0xffffffffu}) {
        struct hal_req r = req(static_cast<enum hal_req_op>(op));
        EXPECT_EQ(run(r), -EINVAL) << op;
    }
    EXPECT_THAT(msgs.text(), HasSubstr("unknown operation"));
}

TEST_F(HalRequest, APinInTheCallersOwnMemoryIsCreatedAndAimedInItsAddressSpace)
{
    rtapi_u32 mem;
    int id = comp("u", 100, &mem);
    ASSERT_EQ(pin(id, mem), 0);
    rtapi_u64 slot;
    std::memcpy(&slot, buf_ + mem, sizeof(slot));
    // the slot holds an address in the owner's mapping, inside the value area
    EXPECT_GE(slot, 0x7f0000000000ull + hal_seg->val_start);
    EXPECT_LT(slot, 0x7f0000000000ull + hal_seg->size);
}

TEST_F(HalRequest, RefusesPinSlotsOutsideTheCallersHalMallocMemory)
{
    rtapi_u32 mem, other_mem;
    int id = comp("u", 100, &mem);
    comp("v", 100, &other_mem);
    hal_test::MsgCapture msgs;
    // the record heap (thread lists, function records, kernel components' memory)
    EXPECT_EQ(pin(id, hal_seg->heap_start + 16), -EINVAL);
    EXPECT_EQ(pin(id, 8), -EINVAL);                        // the segment header
    EXPECT_EQ(pin(id, other_mem), -EINVAL);                // another component's memory
    EXPECT_EQ(pin(id, mem + 60), -EINVAL);                 // runs past the block
    EXPECT_EQ(pin(id, hal_seg->val_top + 64), -EINVAL);    // never allocated
    EXPECT_EQ(pin(id, 0xfffffff8u), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("not in hal_malloc memory of component 'u'"));
    EXPECT_EQ(hal_seg->count[HAL_KIND_PIN], 0u);
}

TEST_F(HalRequest, RefusesAnotherProcesssComponent)
{
    rtapi_u32 mem;
    int id = comp("u", 100, &mem);
    hal_test::MsgCapture msgs;
    EXPECT_EQ(pin(id, mem, 200), -EINVAL);
    struct hal_req m = req(HAL_REQ_MALLOC);
    m.comp_id = id;
    m.value = 8;
    EXPECT_EQ(run(m, 200), -EINVAL);
    struct hal_req ready = req(HAL_REQ_COMP_READY);
    ready.comp_id = id;
    EXPECT_EQ(run(ready, 200), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("component 'u' is not this process's"));
}

TEST_F(HalRequest, RemovesAnotherProcesssComponentOnlyOnceThatProcessIsGone)
{
    pid_t child = fork();
    if (child == 0)
        _exit(0);
    ASSERT_GT(child, 0);
    waitpid(child, nullptr, 0);   // 'child' is now a pid with no process
    rtapi_u32 mem;
    int live = comp("live", static_cast<int>(getpid()), &mem);
    int dead = comp("dead", static_cast<int>(child), &mem);
    hal_test::MsgCapture msgs;
    struct hal_req r = req(HAL_REQ_COMP_EXIT);
    r.comp_id = live;
    EXPECT_EQ(run(r, 300), -EPERM);
    EXPECT_THAT(msgs.text(), HasSubstr("which is running"));
    r.comp_id = dead;
    EXPECT_EQ(run(r, 300), 0);
    EXPECT_EQ(r.arg, 0);   // not the caller's own
    EXPECT_EQ(hal_seg->count[HAL_KIND_COMP], 1u);
}

TEST_F(HalRequest, RefusesLockLevelsOutOfRange)
{
    struct hal_req r = req(HAL_REQ_SET_LOCK);
    r.arg = 0x100;
    EXPECT_EQ(run(r), -EINVAL);
    r.arg = -1;
    EXPECT_EQ(run(r), -EINVAL);
    r.arg = HAL_LOCK_CONFIG;
    EXPECT_EQ(run(r), 0);
    EXPECT_EQ(hal_seg->lock_level, static_cast<rtapi_u32>(HAL_LOCK_CONFIG));
}

TEST_F(HalRequest, TypedWritesCheckTheObjectsTypeAndWriter)
{
    struct hal_req s = req(HAL_REQ_SIG_NEW, "sig");
    s.type = HAL_S32;
    ASSERT_EQ(run(s), 0);
    struct hal_req w = req(HAL_REQ_SET_SIG, "sig");
    w.type = HAL_FLOAT;
    w.value = 5;
    hal_test::MsgCapture msgs;
    EXPECT_EQ(run(w), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("signal 'sig' is s32, not float"));
    w.type = HAL_S32;
    w.value = 0xfffffffbull;   // -5
    EXPECT_EQ(run(w), 0);
    auto* sig = reinterpret_cast<struct hal_sig_rec*>(hal_index_find(hal_seg, HAL_KIND_SIG, "sig"));
    ASSERT_NE(sig, nullptr);
    EXPECT_EQ(hal_sig_value(sig)->s, -5);
    struct hal_req p = req(HAL_REQ_SET_PIN, "nope");
    p.type = HAL_BIT;
    EXPECT_EQ(run(p), -ENOENT);
}

TEST_F(HalRequest, AliasAndUnaliasAreRequestsWithACheckedKind)
{
    rtapi_u32 mem;
    int id = comp("u", 100, &mem);
    ASSERT_EQ(pin(id, mem), 0);
    struct hal_req a = req(HAL_REQ_ALIAS, "u.p", "u.other");
    a.arg = 2;   // neither pin (0) nor param (1)
    hal_test::MsgCapture msgs;
    EXPECT_EQ(run(a), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("alias kind 2 is not valid"));
    a.arg = 0;
    EXPECT_EQ(run(a), 0);
    EXPECT_EQ(hal_seg->alias_count, 1u);
    EXPECT_NE(hal_index_find(hal_seg, HAL_KIND_PIN, "u.other"), nullptr);
    struct hal_req un = req(HAL_REQ_UNALIAS, "u.other");
    EXPECT_EQ(run(un), 0);
    EXPECT_EQ(hal_seg->alias_count, 0u);
    EXPECT_EQ(run(un), -ENOENT);
    struct hal_req lock = req(HAL_REQ_SET_LOCK);
    lock.arg = HAL_LOCK_CONFIG;
    ASSERT_EQ(run(lock), 0);
    EXPECT_EQ(run(a), -EPERM);   // a locked HAL keeps its names
}

TEST_F(HalRequest, SetExactOnlyBeforeTheFirstThread)
{
    struct hal_req r = req(HAL_REQ_SET_EXACT);
    EXPECT_EQ(run(r), 0);
    EXPECT_EQ(hal_seg->exact_periods, 1u);
    hal_seg->count[HAL_KIND_THREAD] = 1;   // as if a thread existed
    hal_test::MsgCapture msgs;
    EXPECT_EQ(run(r), -EBUSY);
    EXPECT_THAT(msgs.text(), HasSubstr("a thread exists already"));
    hal_seg->count[HAL_KIND_THREAD] = 0;
}

TEST_F(HalRequest, RemoveDeadTakesOnlyComponentsWhoseProcessIsGone)
{
    pid_t child = fork();
    if (child == 0)
        _exit(0);
    ASSERT_GT(child, 0);
    waitpid(child, nullptr, 0);
    rtapi_u32 mem;
    int live = comp("live", static_cast<int>(getpid()), &mem);
    int dead = comp("dead", static_cast<int>(child), &mem);
    struct hal_req r = req(HAL_REQ_COMP_REMOVE_DEAD);
    r.comp_id = live;
    EXPECT_EQ(run(r, 300), -EBUSY);
    r.comp_id = 9999;
    EXPECT_EQ(run(r, 300), -ENOENT);
    r.comp_id = 0;   // every dead one
    EXPECT_EQ(run(r, 300), 1);
    EXPECT_EQ(hal_seg->count[HAL_KIND_COMP], 1u);
    r.comp_id = dead;
    EXPECT_EQ(run(r, 300), -ENOENT);
}

TEST_F(HalRequest, SixtyFourBitValuesAreStoredWhole)
{
    struct hal_req s = req(HAL_REQ_SIG_NEW, "big");
    s.type = HAL_U64;
    ASSERT_EQ(run(s), 0);
    struct hal_req w = req(HAL_REQ_SET_SIG, "big");
    w.type = HAL_U64;
    w.value = 0x123456789abcdef0ull;
    EXPECT_EQ(run(w), 0);
    auto* sig = reinterpret_cast<struct hal_sig_rec*>(hal_index_find(hal_seg, HAL_KIND_SIG, "big"));
    ASSERT_NE(sig, nullptr);
    EXPECT_EQ(hal_sig_value(sig)->raw, 0x123456789abcdef0ull);
}

}  // namespace
