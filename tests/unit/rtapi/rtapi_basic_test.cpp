// SPDX-License-Identifier: GPL-2.0-or-later
// rtapi_basic_test - modules, messages, clock period, time, priorities and mutexes of
// the simulated-realtime RTAPI (user flavor; the same code is in rtapi_rt).
#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "rtapi.h"
#include "rtapi_mutex_uspace.h"

namespace {

std::vector<std::pair<int, std::string>> captured;

void capture(msg_level_t level, const char* msg)
{
    captured.emplace_back(level, msg);
}

// Installs the capturing handler for one test and restores everything after.
class RtapiMessages : public ::testing::Test {
protected:
    void SetUp() override
    {
        captured.clear();
        old_level_ = rtapi_get_msg_level();
        rtapi_set_msg_handler(capture);
    }
    void TearDown() override
    {
        rtapi_set_msg_handler(nullptr);
        rtapi_set_msg_level(old_level_);
    }
    int old_level_ = 0;
};

TEST_F(RtapiMessages, DefaultLevelIsWarnings)
{
    // The test runs without RTAPI_MSG_LEVEL in the environment (ctest passes none).
    if (getenv("RTAPI_MSG_LEVEL"))
        GTEST_SKIP() << "RTAPI_MSG_LEVEL is set";
    EXPECT_EQ(old_level_, RTAPI_MSG_WARN);
}

TEST_F(RtapiMessages, PrintMsgFiltersByLevel)
{
    ASSERT_EQ(rtapi_set_msg_level(RTAPI_MSG_WARN), 0);
    rtapi_print_msg(RTAPI_MSG_ERR, "err %d\n", 1);
    rtapi_print_msg(RTAPI_MSG_WARN, "warn %s\n", "two");
    rtapi_print_msg(RTAPI_MSG_INFO, "info\n");
    rtapi_print_msg(RTAPI_MSG_DBG, "debug\n");
    ASSERT_EQ(captured.size(), 2u);
    EXPECT_EQ(captured[0], std::make_pair(int(RTAPI_MSG_ERR), std::string("err 1\n")));
    EXPECT_EQ(captured[1], std::make_pair(int(RTAPI_MSG_WARN), std::string("warn two\n")));
}

TEST_F(RtapiMessages, PrintAlwaysDeliversAtLevelAll)
{
    rtapi_set_msg_level(RTAPI_MSG_NONE);
    rtapi_print("plain %.2f\n", 1.5);
    ASSERT_EQ(captured.size(), 1u);
    EXPECT_EQ(captured[0].first, RTAPI_MSG_ALL);
    EXPECT_EQ(captured[0].second, "plain 1.50\n");
}

TEST_F(RtapiMessages, SetMsgLevelRefusesOutOfRange)
{
    EXPECT_EQ(rtapi_set_msg_level(-1), -EINVAL);
    EXPECT_EQ(rtapi_set_msg_level(RTAPI_MSG_ALL + 1), -EINVAL);
    EXPECT_EQ(rtapi_get_msg_level(), old_level_);
    EXPECT_EQ(rtapi_set_msg_level(RTAPI_MSG_ALL), 0);
    EXPECT_EQ(rtapi_get_msg_level(), RTAPI_MSG_ALL);
}

TEST_F(RtapiMessages, HandlerCanBeQueriedAndReset)
{
    EXPECT_EQ(rtapi_get_msg_handler(), &capture);
    rtapi_set_msg_handler(nullptr);
    EXPECT_NE(rtapi_get_msg_handler(), &capture);
    EXPECT_NE(rtapi_get_msg_handler(), nullptr);
}

TEST_F(RtapiMessages, LongMessagesAreCutWithAnEllipsis)
{
    std::string big(3000, 'x');
    rtapi_print("%s\n", big.c_str());
    ASSERT_EQ(captured.size(), 1u);
    EXPECT_EQ(captured[0].second.size(), 1023u);
    EXPECT_EQ(captured[0].second.substr(1019), "...\n");
}

TEST(RtapiDefaultHandler, WritesToStderr)
{
    testing::internal::CaptureStderr();
    rtapi_print("to stderr %d\n", 5);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "to stderr 5\n");
}

TEST_F(RtapiMessages, InitGivesIdsAndExitReleasesThem)
{
    int a = rtapi_init("first");
    int b = rtapi_init("a-module-name-that-is-much-longer-than-31-characters");
    ASSERT_GT(a, 0);
    ASSERT_GT(b, 0);
    EXPECT_NE(a, b);
    EXPECT_EQ(rtapi_exit(a), 0);
    EXPECT_EQ(rtapi_exit(b), 0);
    EXPECT_TRUE(captured.empty());
}

TEST_F(RtapiMessages, ExitOfAnUnknownModuleFails)
{
    EXPECT_EQ(rtapi_exit(0), -EINVAL);
    EXPECT_EQ(rtapi_exit(100000), -EINVAL);
    int id = rtapi_init("once");
    ASSERT_GT(id, 0);
    ASSERT_EQ(rtapi_exit(id), 0);
    EXPECT_EQ(rtapi_exit(id), -EINVAL);
    ASSERT_FALSE(captured.empty());
    EXPECT_EQ(captured.back().second, "rtapi: rtapi_exit(" + std::to_string(id) + "): no such module\n");
}

// The clock can be started once per process, so every rule is in this one test.
TEST_F(RtapiMessages, ClockPeriodIsSetOnceAndQueriedWithZero)
{
    EXPECT_EQ(rtapi_clock_set_period(0), 0);
    EXPECT_EQ(rtapi_delay_max(), 10000);
    EXPECT_EQ(rtapi_clock_set_period(-5), -EINVAL);
    EXPECT_EQ(rtapi_clock_set_period(10), -EINVAL);
    EXPECT_EQ(captured.back().second, "rtapi: clock period 10 ns refused: must be 1000..10000000000 ns\n");
    EXPECT_EQ(rtapi_clock_set_period(0), 0);
    EXPECT_EQ(rtapi_clock_set_period(1000000), 1000000);
    EXPECT_EQ(rtapi_clock_set_period(0), 1000000);
    EXPECT_EQ(rtapi_clock_set_period(500000), -EINVAL);
    EXPECT_EQ(captured.back().second, "rtapi: clock period 500000 ns refused: the clock already runs with 1000000 ns\n");
    EXPECT_EQ(rtapi_clock_set_period(0), 1000000);
    EXPECT_EQ(rtapi_delay_max(), 250000);
}

TEST(RtapiModule, GetpidIsTheProcessId)
{
    EXPECT_EQ(rtapi_getpid(), (long)getpid());
}

// rtapi_getpid() caches the pid (the HAL lock asks for it every time); a fork's
// child must get its own, not the cached parent's, and so must its HAL lock word
TEST(RtapiModule, GetpidInAForkedChildIsTheChilds)
{
    ASSERT_EQ(rtapi_getpid(), (long)getpid());   // cached now
    unsigned long parent_word = rtapi_mutex_self_word();
    pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        bool ok = rtapi_getpid() == (long)getpid() && rtapi_getpid() != (long)getppid() &&
                  rtapi_mutex_word_pid(rtapi_mutex_self_word()) == (int)getpid() &&
                  rtapi_mutex_self_word() != parent_word;
        _exit(ok ? 0 : 1);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    EXPECT_EQ(rtapi_getpid(), (long)getpid());
}

TEST(RtapiTime, TimeIsMonotonicAndSleepsWait)
{
    long long t0 = rtapi_get_time();
    long long c0 = rtapi_get_clocks();
    rtapi_sleep_ns(2000000);
    long long t1 = rtapi_get_time();
    EXPECT_GE(t1 - t0, 2000000);
    EXPECT_GT(rtapi_get_clocks(), c0);
    rtapi_delay(5000);
    EXPECT_GE(rtapi_get_time() - t1, 5000);
}

TEST(RtapiTime, DelayIsCappedAtDelayMax)
{
    long long t0 = rtapi_get_time();
    rtapi_delay(1000000000L);  // one second asked: capped at rtapi_delay_max()
    EXPECT_LT(rtapi_get_time() - t0, 500000000LL);
}

TEST(RtapiPrio, HigherNumbersAreHigherPriorities)
{
    int hi = rtapi_prio_highest(), lo = rtapi_prio_lowest();
    EXPECT_GT(hi, lo);
    EXPECT_EQ(rtapi_prio_next_higher(lo), lo + 1);
    EXPECT_EQ(rtapi_prio_next_lower(hi), hi - 1);
    EXPECT_EQ(rtapi_prio_next_higher(hi), hi);
    EXPECT_EQ(rtapi_prio_next_lower(lo), lo);
}

TEST(RtapiMutex, TryGiveAndGet)
{
    unsigned long m = 0;
    EXPECT_EQ(rtapi_mutex_try(&m), 0);
    EXPECT_NE(rtapi_mutex_try(&m), 0);
    rtapi_mutex_give(&m);
    EXPECT_EQ(rtapi_mutex_try(&m), 0);
    std::thread other([&] { rtapi_mutex_give(&m); });  // get() must wait for this
    rtapi_mutex_get(&m);
    other.join();
    EXPECT_NE(rtapi_mutex_try(&m), 0);
    rtapi_mutex_give(&m);
}

TEST(RtapiMutex, GetSerializesThreads)
{
    unsigned long m = 0;
    long counter = 0;
    auto work = [&] {
        for (int i = 0; i < 20000; i++) {
            rtapi_mutex_get(&m);
            counter++;
            rtapi_mutex_give(&m);
        }
    };
    std::thread a(work), b(work);
    a.join();
    b.join();
    EXPECT_EQ(counter, 40000);
}



// --- the holder record (rtapi_mutex_uspace.h): a process that dies holding a lock
// shared with other processes does not block them forever (issue 19, item 1) ---

// A mutex word in memory shared with a child process.
class SharedWord {
public:
    SharedWord()
    {
        void* p = mmap(nullptr, sizeof(unsigned long), PROT_READ | PROT_WRITE,
                       MAP_SHARED | MAP_ANONYMOUS, -1, 0);
        word_ = p == MAP_FAILED ? nullptr : static_cast<unsigned long*>(p);
        if (word_)
            *word_ = 0;
    }
    ~SharedWord()
    {
        if (word_)
            munmap(word_, sizeof(unsigned long));
    }
    unsigned long* get() { return word_; }

private:
    unsigned long* word_;
};

// Fork a child that takes the lock, tells us on a pipe, then stays until killed
// ('linger') or exits at once still holding it.
pid_t child_taking(unsigned long* m, bool linger)
{
    int p[2];
    if (pipe(p) != 0)
        return -1;
    pid_t pid = fork();
    if (pid == 0) {
        rtapi_mutex_get(m);
        char c = 'x';
        (void)!write(p[1], &c, 1);
        while (linger)
            pause();
        _exit(0);
    }
    char c;
    close(p[1]);
    (void)!read(p[0], &c, 1);
    close(p[0]);
    return pid;
}

TEST(RtapiMutexHolder, HolderWritesItsPidAndGiveClearsTheWord)
{
    unsigned long m = 0;
    rtapi_mutex_get(&m);
    EXPECT_EQ(rtapi_mutex_word_pid(m), getpid());
    EXPECT_EQ(rtapi_mutex_holder_state(m), RTAPI_MUTEX_HOLDER_ALIVE);
    EXPECT_NE(rtapi_mutex_try(&m), 0);  // try() sees it held
    rtapi_mutex_give(&m);
    EXPECT_EQ(m, 0UL);
}

TEST(RtapiMutexHolder, DeadHolderIsTakenOverAfterReaping)
{
    SharedWord w;
    ASSERT_NE(w.get(), nullptr);
    pid_t child = child_taking(w.get(), false);
    ASSERT_GT(child, 0);
    int status;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    EXPECT_EQ(rtapi_mutex_word_pid(*w.get()), child);
    int recovered = -1;
    EXPECT_EQ(rtapi_mutex_try_recover(w.get(), &recovered), 0UL);
    EXPECT_EQ(recovered, child);
    EXPECT_EQ(rtapi_mutex_word_pid(*w.get()), getpid());
    rtapi_mutex_give(w.get());
}

TEST(RtapiMutexHolder, ZombieHolderIsDeadAndGetReturns)
{
    SharedWord w;
    ASSERT_NE(w.get(), nullptr);
    pid_t child = child_taking(w.get(), true);
    ASSERT_GT(child, 0);
    kill(child, SIGKILL);
    // Not reaped yet: a zombie holds nothing. get() must return (it would hang before).
    rtapi_mutex_get(w.get());
    EXPECT_EQ(rtapi_mutex_word_pid(*w.get()), getpid());
    rtapi_mutex_give(w.get());
    int status;
    waitpid(child, &status, 0);
}

TEST(RtapiMutexHolder, LiveHolderIsNotTakenOver)
{
    SharedWord w;
    ASSERT_NE(w.get(), nullptr);
    pid_t child = child_taking(w.get(), true);
    ASSERT_GT(child, 0);
    int recovered = -1;
    unsigned long held = rtapi_mutex_try_recover(w.get(), &recovered);
    EXPECT_EQ(rtapi_mutex_word_pid(held), child);
    EXPECT_EQ(recovered, 0);
    EXPECT_EQ(rtapi_mutex_holder_state(held), RTAPI_MUTEX_HOLDER_ALIVE);
    kill(child, SIGKILL);
    int status;
    waitpid(child, &status, 0);
    EXPECT_EQ(rtapi_mutex_try_recover(w.get(), &recovered), 0UL);
    EXPECT_EQ(recovered, child);
    rtapi_mutex_give(w.get());
}

TEST(RtapiMutexHolder, RecycledPidAndMissingRecord)
{
    unsigned long me = rtapi_mutex_self_word();
    EXPECT_EQ(rtapi_mutex_holder_state(me), RTAPI_MUTEX_HOLDER_ALIVE);
    // Same pid, another start time: the pid now names a different process.
    EXPECT_EQ(rtapi_mutex_holder_state(me ^ (1UL << 40)), RTAPI_MUTEX_HOLDER_DEAD);
    // Taken by try() (or realtime code): no record, never taken over.
    unsigned long m = 0;
    EXPECT_EQ(rtapi_mutex_try(&m), 0);
    EXPECT_EQ(rtapi_mutex_holder_state(m), RTAPI_MUTEX_HOLDER_UNKNOWN);
    int recovered = -1;
    EXPECT_NE(rtapi_mutex_try_recover(&m, &recovered), 0UL);
    EXPECT_EQ(recovered, 0);
}

}  // namespace
