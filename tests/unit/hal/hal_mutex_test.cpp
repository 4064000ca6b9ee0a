// SPDX-License-Identifier: GPL-2.0-or-later
// hal_mutex_test.cpp - the HAL mutex's holder record (hal_lock.c) on a private
// segment, with process liveness injected: a dead holder is recovered once, with a
// message naming it; a live one is not; the window before the holder is recorded is
// respected.
#include <gtest/gtest.h>
#include <gmock/gmock.h>

#include <cstdlib>
#include <cstring>
#include <set>

#include "hal_test_internal.h"
#include "msg_capture.hpp"

namespace {

using ::testing::HasSubstr;

constexpr rtapi_u32 kSegSize = 4u << 20;   // the name index alone is 1 MiB

std::set<int>& dead_pids()
{
    static std::set<int> dead;
    return dead;
}
bool fake_alive(int pid) { return dead_pids().count(pid) == 0; }

class HalMutex : public ::testing::Test {
protected:
    void SetUp() override
    {
        seg_ = static_cast<struct hal_seg_hdr*>(std::aligned_alloc(4096, kSegSize));
        ASSERT_NE(seg_, nullptr);
        hal_segment_init(seg_, kSegSize);
        dead_pids().clear();
        hal_lock_set_liveness_check(fake_alive);
    }
    void TearDown() override
    {
        hal_lock_set_liveness_check(nullptr);
        std::free(seg_);
    }
    struct hal_seg_hdr* seg_ = nullptr;
};

TEST_F(HalMutex, AFreeMutexIsTakenAndItsHolderRecorded)
{
    int dead = -1;
    EXPECT_EQ(hal_lock_try(seg_, 101, "halcmd", &dead), 0);
    EXPECT_EQ(dead, 0);
    EXPECT_EQ(seg_->mutex_pid, 101);
    EXPECT_STREQ(seg_->mutex_holder, "halcmd");
    hal_lock_give(seg_);
    EXPECT_EQ(seg_->mutex_pid, 0);
    EXPECT_EQ(seg_->mutex, 0u);
}

TEST_F(HalMutex, ALiveHolderKeepsIt)
{
    int dead;
    ASSERT_EQ(hal_lock_try(seg_, 101, "halcmd", &dead), 0);
    EXPECT_EQ(hal_lock_try(seg_, 202, "rtapi_app", &dead), -EBUSY);
    EXPECT_EQ(seg_->mutex_pid, 101);
}

TEST_F(HalMutex, ADeadHolderIsRecoveredOnceAndNamed)
{
    int dead;
    ASSERT_EQ(hal_lock_try(seg_, 101, "halcmd", &dead), 0);
    dead_pids().insert(101);
    EXPECT_EQ(hal_lock_try(seg_, 202, "rtapi_app", &dead), 0);
    EXPECT_EQ(dead, 101);
    EXPECT_EQ(seg_->mutex_pid, 202);
    EXPECT_STREQ(seg_->mutex_holder, "rtapi_app");
    // a second waiter finds the new, live holder: no double recovery
    EXPECT_EQ(hal_lock_try(seg_, 303, "halmeter", &dead), -EBUSY);
    EXPECT_EQ(seg_->mutex_pid, 202);
}

TEST_F(HalMutex, AHolderNotYetRecordedIsNotTakenOver)
{
    int dead;
    seg_->mutex = 1;   // taken by something that recorded no pid
    dead_pids().insert(0);
    EXPECT_EQ(hal_lock_try(seg_, 202, "rtapi_app", &dead), -EBUSY);
}

TEST_F(HalMutex, LockingRecoversFromADeadHolderWithAMessageNamingIt)
{
    int dead;
    ASSERT_EQ(hal_lock_try(seg_, 4242, "oldhalcmd", &dead), 0);
    dead_pids().insert(4242);
    hal_test::MsgCapture msgs;
    hal_lock_seg(seg_);   // would hang forever without recovery
    EXPECT_THAT(msgs.text(), HasSubstr("held by pid 4242 (oldhalcmd), which is gone: recovered"));
    EXPECT_NE(seg_->mutex_pid, 4242);
    hal_lock_give(seg_);
}

}  // namespace
