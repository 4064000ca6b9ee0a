// SPDX-License-Identifier: GPL-2.0-or-later
// rtapi_task_test - periodic tasks of the simulated-realtime flavor. Timing is only
// checked with loose bounds (a loaded CI machine may delay threads a lot): the point
// is behaviour — tasks run, pause, resume, stop and are deleted without leaking.
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rtapi.h"

namespace {

std::vector<std::string> messages;
std::vector<std::string> warnings;

void capture_warnings(msg_level_t level, const char* msg)
{
    if (level == RTAPI_MSG_WARN)
        warnings.emplace_back(msg);
}

void capture(msg_level_t level, const char* msg)
{
    if (level <= RTAPI_MSG_ERR)  // the one-time SCHED_FIFO warning is not an error
        messages.emplace_back(msg);
}

class RtapiTask : public ::testing::Test {
protected:
    void SetUp() override
    {
        messages.clear();
        rtapi_set_msg_handler(capture);
    }
    void TearDown() override { rtapi_set_msg_handler(nullptr); }
    int prio_ = rtapi_prio_highest();
};

struct Counter {
    std::atomic<long> cycles{0};
    std::atomic<int> self{0};
};

// The usual shape of a task: an infinite loop around rtapi_task_wait().
void count_forever(void* arg)
{
    auto* c = static_cast<Counter*>(arg);
    c->self = rtapi_task_self();
    for (;;) {
        c->cycles++;
        rtapi_task_wait();
    }
}

TEST_F(RtapiTask, PeriodicTaskRunsAboutOncePerPeriod)
{
    Counter c;
    int id = rtapi_task_new(count_forever, &c, prio_, 0, 1);
    ASSERT_GT(id, 0);
    rtapi_sleep_ns(20000000);
    EXPECT_EQ(c.cycles, 0) << "a new task must wait for start or resume";
    ASSERT_EQ(rtapi_task_start(id, 1000000), 0);
    rtapi_sleep_ns(50000000);
    long n = c.cycles;
    EXPECT_GE(n, 10);
    EXPECT_LE(n, 100);
    EXPECT_EQ(c.self, id);
    EXPECT_GE(rtapi_task_overruns(id), 0);
    EXPECT_EQ(rtapi_task_delete(id), 0);
    EXPECT_TRUE(messages.empty());
}

TEST_F(RtapiTask, PauseStopsTheTaskAndStartOrResumeContinue)
{
    Counter c;
    int id = rtapi_task_new(count_forever, &c, prio_, 0, 0);
    ASSERT_GT(id, 0);
    ASSERT_EQ(rtapi_task_start(id, 1000000), 0);
    rtapi_sleep_ns(20000000);
    ASSERT_EQ(rtapi_task_pause(id), 0);
    rtapi_sleep_ns(5000000);  // let a cycle in flight finish
    long paused_at = c.cycles;
    rtapi_sleep_ns(30000000);
    EXPECT_EQ(c.cycles, paused_at);
    EXPECT_EQ(rtapi_task_start(id, 2000000), 0);
    rtapi_sleep_ns(30000000);
    EXPECT_GT(c.cycles, paused_at);
    EXPECT_EQ(rtapi_task_start(id, 1000000), -EBUSY);  // running: pause first
    ASSERT_EQ(rtapi_task_pause(id), 0);
    rtapi_sleep_ns(5000000);
    long before_resume = c.cycles;
    EXPECT_EQ(rtapi_task_resume(id), 0);  // free-running: no period at all
    rtapi_sleep_ns(20000000);
    EXPECT_GT(c.cycles, before_resume + 10);
    EXPECT_EQ(rtapi_task_resume(id), -EBUSY);
    EXPECT_EQ(rtapi_task_delete(id), 0);
}

TEST_F(RtapiTask, DeletingAnInfiniteLoopTaskStopsIt)
{
    for (int round = 0; round < 20; round++) {  // would leak threads or slots if broken
        Counter c;
        int id = rtapi_task_new(count_forever, &c, prio_, 16384, 0);
        ASSERT_GT(id, 0);
        ASSERT_EQ(rtapi_task_start(id, 500000), 0);
        rtapi_sleep_ns(2000000);
        ASSERT_EQ(rtapi_task_delete(id), 0);
        long after = c.cycles;
        rtapi_sleep_ns(3000000);
        EXPECT_EQ(c.cycles, after);
    }
}

TEST_F(RtapiTask, DeletingANeverStartedOrPausedTaskWorks)
{
    Counter c;
    int id = rtapi_task_new(count_forever, &c, prio_, 0, 0);
    ASSERT_GT(id, 0);
    EXPECT_EQ(rtapi_task_delete(id), 0);
    EXPECT_EQ(c.cycles, 0);
    id = rtapi_task_new(count_forever, &c, prio_, 0, 0);
    ASSERT_EQ(rtapi_task_start(id, 1000000), 0);
    rtapi_sleep_ns(5000000);
    ASSERT_EQ(rtapi_task_pause(id), 0);
    EXPECT_EQ(rtapi_task_delete(id), 0);
}

void return_at_once(void* arg)
{
    static_cast<Counter*>(arg)->cycles++;
}

TEST_F(RtapiTask, TaskCodeMayReturn)
{
    Counter c;
    int id = rtapi_task_new(return_at_once, &c, prio_, 0, 0);
    ASSERT_EQ(rtapi_task_resume(id), 0);
    rtapi_sleep_ns(10000000);
    EXPECT_EQ(c.cycles, 1);
    EXPECT_EQ(rtapi_task_delete(id), 0);
}

void overrun_once(void* arg)
{
    auto* c = static_cast<Counter*>(arg);
    for (;;) {
        if (c->cycles++ == 2)
            rtapi_sleep_ns(25000000);  // miss about 25 periods of 1 ms
        rtapi_task_wait();
    }
}

TEST_F(RtapiTask, MissedPeriodsAreCountedAsOverruns)
{
    Counter c;
    int id = rtapi_task_new(overrun_once, &c, prio_, 0, 0);
    ASSERT_EQ(rtapi_task_start(id, 1000000), 0);
    for (int i = 0; i < 400 && c.cycles < 4; i++)  // up to 2 s on a busy machine
        rtapi_sleep_ns(5000000);
    ASSERT_GE(c.cycles, 4);
    long long over = rtapi_task_overruns(id);
    EXPECT_GE(over, 24);  // released 25 ms late: at least 24 whole periods skipped
    EXPECT_LE(over, 2000);
    EXPECT_EQ(rtapi_task_delete(id), 0);
}

void pause_self(void* arg)
{
    auto* c = static_cast<Counter*>(arg);
    for (;;) {
        c->cycles++;
        rtapi_task_pause(rtapi_task_self());
        rtapi_task_wait();
    }
}

TEST_F(RtapiTask, ATaskCanPauseItself)
{
    Counter c;
    int id = rtapi_task_new(pause_self, &c, prio_, 0, 0);
    ASSERT_EQ(rtapi_task_start(id, 1000000), 0);
    rtapi_sleep_ns(20000000);
    EXPECT_EQ(c.cycles, 1);
    ASSERT_EQ(rtapi_task_start(id, 1000000), 0);
    rtapi_sleep_ns(20000000);
    EXPECT_EQ(c.cycles, 2);
    EXPECT_EQ(rtapi_task_delete(id), 0);
}

TEST_F(RtapiTask, BadCallsAreRefusedWithAMessage)
{
    Counter c;
    EXPECT_EQ(rtapi_task_new(nullptr, &c, prio_, 0, 0), -EINVAL);
    EXPECT_EQ(messages.back(), "rtapi: rtapi_task_new: no task code\n");
    EXPECT_EQ(rtapi_task_new(count_forever, &c, rtapi_prio_highest() + 1, 0, 0), -EINVAL);
    EXPECT_EQ(messages.back(), "rtapi: rtapi_task_new: priority " + std::to_string(rtapi_prio_highest() + 1) +
                                   " outside " + std::to_string(rtapi_prio_lowest()) + ".." +
                                   std::to_string(rtapi_prio_highest()) + "\n");
    EXPECT_EQ(rtapi_task_start(99, 1000000), -EINVAL);
    EXPECT_EQ(messages.back(), "rtapi: rtapi_task_start(99): no such task\n");
    EXPECT_EQ(rtapi_task_delete(0), -EINVAL);
    EXPECT_EQ(rtapi_task_pause(-1), -EINVAL);
    EXPECT_EQ(rtapi_task_resume(65), -EINVAL);
    EXPECT_EQ(rtapi_task_overruns(99), -EINVAL);
    EXPECT_EQ(rtapi_task_self(), -EINVAL);
    int id = rtapi_task_new(count_forever, &c, prio_, 0, 0);
    EXPECT_EQ(rtapi_task_start(id, 0), -EINVAL);
    EXPECT_EQ(messages.back(), "rtapi: rtapi_task_start(" + std::to_string(id) +
                                   "): period 0 ns is not 1..10000000000\n");
    EXPECT_EQ(rtapi_task_delete(id), 0);
    rtapi_task_wait();
    EXPECT_EQ(messages.back(), "rtapi: rtapi_task_wait called outside a task\n");
}

void count_forever(void* arg);

// Without the right to use SCHED_FIFO (here: after giving up root), tasks still run,
// with normal scheduling and at most one warning for the whole process.
[[noreturn]] void run_two_tasks_without_root()
{
    if (geteuid() == 0 && setuid(65534) != 0)
        _exit(3);
    rtapi_set_msg_handler(capture_warnings);
    Counter a;
    Counter b;
    int ia = rtapi_task_new(count_forever, &a, rtapi_prio_highest(), 0, 0);
    int ib = rtapi_task_new(count_forever, &b, rtapi_prio_lowest(), 0, 0);
    if (ia <= 0 || ib <= 0 || rtapi_task_start(ia, 1000000) || rtapi_task_start(ib, 1000000))
        _exit(4);
    for (int i = 0; i < 400 && (a.cycles < 3 || b.cycles < 3); i++)
        rtapi_sleep_ns(5000000);
    if (a.cycles < 3 || b.cycles < 3)
        _exit(5);
    if (rtapi_task_delete(ia) || rtapi_task_delete(ib))
        _exit(6);
    if (warnings.size() > 1)
        _exit(7);
    if (warnings.size() == 1)  // none when an rtprio limit allows FIFO
        fprintf(stderr, "%s", warnings[0].c_str());
    _exit(0);
}

TEST(RtapiTaskDeathTest, WithoutFifoTasksRunAndWarnOnce)
{
    EXPECT_EXIT(run_two_tasks_without_root(), testing::ExitedWithCode(0),
                "^(rtapi: SCHED_FIFO not permitted \\(needs root, CAP_SYS_NICE or an rtprio limit\\): "
                "tasks run with normal scheduling and poor timing\n)?$");
}

TEST_F(RtapiTask, TableFullIsReported)
{
    Counter c;
    std::vector<int> ids;
    int id;
    while ((id = rtapi_task_new(count_forever, &c, prio_, 0, 0)) > 0)
        ids.push_back(id);
    EXPECT_EQ(id, -ENOMEM);
    EXPECT_EQ(messages.back(), "rtapi: rtapi_task_new: all 64 tasks in use\n");
    for (int i : ids)
        EXPECT_EQ(rtapi_task_delete(i), 0);
    id = rtapi_task_new(count_forever, &c, prio_, 0, 0);
    EXPECT_GT(id, 0);
    EXPECT_EQ(rtapi_task_delete(id), 0);
}

}  // namespace
