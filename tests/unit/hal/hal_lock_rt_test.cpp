// SPDX-License-Identifier: GPL-2.0-or-later
// hal_lock_rt_test.cpp - lock levels (hal_set_lock(3hal), RULINGS.md): each level
// refuses exactly its operations with -EPERM and a message, and changes nothing.
#include "hal_rt_fixture.hpp"

#include <functional>
#include <map>

namespace hal_test {
namespace {

using ::testing::HasSubstr;

void nothing(void*, long) {}

// One operation that a lock level may refuse. 'run' attempts it; 'undo' takes a
// success back (called unlocked) so the next level sees the same HAL.
struct Op {
    const char* name;
    unsigned level;   // the HAL_LOCK_* bit that refuses it, 0 = never refused
    std::function<int()> run;
    std::function<void()> undo;
};

class HalLock : public HalRt {
protected:
    void SetUp() override
    {
        HalRt::SetUp();
        vals_ = mem<ParamVals>();
        ASSERT_NE(vals_, nullptr);
        ASSERT_EQ(hal_pin_float_new("rt.in", HAL_IN, &pins_->f[0], comp_), 0);
        ASSERT_EQ(hal_pin_float_new("rt.linked", HAL_IN, &pins_->f[1], comp_), 0);
        ASSERT_EQ(hal_param_float_new("rt.gain", HAL_RW, &vals_->f, comp_), 0);
        ASSERT_EQ(hal_export_funct("rt.f", nothing, nullptr, 0, 0, comp_), 0);
        ASSERT_EQ(hal_export_funct("rt.on", nothing, nullptr, 0, 0, comp_), 0);
        ASSERT_EQ(new_thread("t1", 1000000, 0), 0);
        ASSERT_EQ(hal_add_funct_to_thread("rt.on", "t1", 1), 0);
        ASSERT_EQ(new_signal("s", HAL_FLOAT), 0);
        ASSERT_EQ(new_signal("s.del", HAL_FLOAT), 0);
        ASSERT_EQ(hal_link("rt.linked", "s"), 0);
    }

    std::vector<Op> ops()
    {
        return {
            {"hal_pin_new", HAL_LOCK_LOAD,
             [this] { return hal_pin_bit_newf(HAL_IN, &pins_->b[0], comp_, "rt.p%d", n_++); }, [] {}},
            {"hal_param_new", HAL_LOCK_LOAD,
             [this] { return hal_param_bit_newf(HAL_RW, &vals_->b, comp_, "rt.q%d", n_++); }, [] {}},
            {"hal_export_funct", HAL_LOCK_LOAD,
             [this] {
                 return hal_export_funct(("rt.g" + std::to_string(n_++)).c_str(), nothing, nullptr, 0, 0, comp_);
             },
             [] {}},
            {"hal_create_thread", HAL_LOCK_LOAD, [] { return hal_create_thread("t2", 2000000, 0); },
             [] { hal_thread_delete("t2"); }},
            {"hal_signal_new", HAL_LOCK_CONFIG, [] { return hal_signal_new("s.new", HAL_BIT); },
             [] { hal_signal_delete("s.new"); }},
            {"hal_signal_delete", HAL_LOCK_CONFIG, [] { return hal_signal_delete("s.del"); },
             [] { hal_signal_new("s.del", HAL_FLOAT); }},
            {"hal_link", HAL_LOCK_CONFIG, [] { return hal_link("rt.in", "s"); }, [] { hal_unlink("rt.in"); }},
            {"hal_unlink", HAL_LOCK_CONFIG, [] { return hal_unlink("rt.linked"); },
             [] { hal_link("rt.linked", "s"); }},
            {"hal_add_funct_to_thread", HAL_LOCK_CONFIG, [] { return hal_add_funct_to_thread("rt.f", "t1", 1); },
             [] { hal_del_funct_from_thread("rt.f", "t1"); }},
            {"hal_del_funct_from_thread", HAL_LOCK_CONFIG, [] { return hal_del_funct_from_thread("rt.on", "t1"); },
             [] { hal_add_funct_to_thread("rt.on", "t1", 1); }},
            {"hal_start_threads", HAL_LOCK_RUN, [] { return hal_start_threads(); }, [] { hal_stop_threads(); }},
            {"hal_stop_threads", HAL_LOCK_RUN, [] { return hal_stop_threads(); }, [] {}},
            {"hal_param_set", 0, [] { return hal_param_float_set("rt.gain", 1.5); }, [] {}},
            {"hal_ready", 0, [this] { return hal_ready(comp_); }, [] {}},
            // Last: a new component becomes the owner of later threads and hal_malloc().
            {"hal_init", HAL_LOCK_LOAD, [] { return hal_init("rt.new"); },
             [] { hal_exit(comp_rec("rt.new")->comp_id); }},
        };
    }

    // Every operation under 'level': refused iff its bit is set in 'level'.
    void check_level(unsigned level)
    {
        for (auto& op : ops()) {
            ASSERT_EQ(hal_set_lock(static_cast<unsigned char>(level)), 0);
            rtapi_u32 used = hal_seg->bytes_used;
            MsgCapture msgs;
            int rc = op.run();
            ASSERT_EQ(hal_set_lock(HAL_LOCK_NONE), 0);
            if (op.level & level) {
                EXPECT_EQ(rc, -EPERM) << op.name << " under lock " << level;
                EXPECT_THAT(msgs.text(), HasSubstr("HAL is locked")) << op.name;
                EXPECT_EQ(hal_seg->bytes_used, used) << op.name << " changed the HAL while refused";
            } else {
                EXPECT_GE(rc, 0) << op.name << " under lock " << level;
                if (rc >= 0)
                    op.undo();
            }
        }
        EXPECT_EQ(hal_get_lock(), HAL_LOCK_NONE);
    }

    ParamVals* vals_ = nullptr;
    int n_ = 0;
};

TEST_F(HalRt, GetLockReturnsWhatSetLockSet)
{
    EXPECT_EQ(hal_get_lock(), HAL_LOCK_NONE);
    ASSERT_EQ(hal_set_lock(HAL_LOCK_CONFIG | HAL_LOCK_RUN), 0);
    EXPECT_EQ(hal_get_lock(), HAL_LOCK_CONFIG | HAL_LOCK_RUN);
    ASSERT_EQ(hal_set_lock(HAL_LOCK_NONE), 0);
    EXPECT_EQ(hal_get_lock(), HAL_LOCK_NONE);
}

TEST_F(HalLock, NoLockRefusesNothing) { check_level(HAL_LOCK_NONE); }
TEST_F(HalLock, LoadLockRefusesCreatingComponentsPinsParamsFunctionsAndThreads) { check_level(HAL_LOCK_LOAD); }
TEST_F(HalLock, ConfigLockRefusesSignalsLinksAndThreadFunctionLists) { check_level(HAL_LOCK_CONFIG); }
TEST_F(HalLock, ParamsLockRefusesNoneOfTheseOperations) { check_level(HAL_LOCK_PARAMS); }
TEST_F(HalLock, RunLockRefusesStartingAndStoppingThreads) { check_level(HAL_LOCK_RUN); }
TEST_F(HalLock, AllLockRefusesEveryLockedOperation) { check_level(HAL_LOCK_ALL); }

TEST_F(HalLock, TheMessageNamesTheLevelAndTheOperation)
{
    ASSERT_EQ(hal_set_lock(HAL_LOCK_CONFIG), 0);
    MsgCapture msgs;
    EXPECT_EQ(hal_link("rt.in", "s"), -EPERM);
    EXPECT_THAT(msgs.text(), HasSubstr("HAL is locked (config): cannot link pins; use 'unlock config' first"));
}

TEST_F(HalLock, ARefusedLinkLeavesThePinUnlinked)
{
    ASSERT_EQ(hal_set_lock(HAL_LOCK_CONFIG), 0);
    EXPECT_EQ(hal_link("rt.in", "s"), -EPERM);
    EXPECT_EQ(pin_rec("rt.in")->signal_off, 0u);
    EXPECT_EQ(hal_unlink("rt.linked"), -EPERM);
    EXPECT_NE(pin_rec("rt.linked")->signal_off, 0u);
}

TEST_F(HalLock, ExitStillWorksUnderALoadLock)
{
    int id = hal_init("rt.leaving");
    ASSERT_GT(id, 0);
    ASSERT_EQ(hal_set_lock(HAL_LOCK_ALL), 0);
    EXPECT_EQ(hal_exit(id), 0);   // unloading is never locked out (halcmd unloadrt all)
}

}  // namespace
}  // namespace hal_test
