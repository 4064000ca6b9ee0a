// SPDX-License-Identifier: GPL-2.0-or-later
// hal_funct_thread_rt_test.cpp - functions (hal_export_funct(3hal)), their places in
// threads (hal_add_funct_to_thread(3hal)) and threads that really run them.
#include "hal_rt_fixture.hpp"

#include <atomic>
#include <memory>
#include <string>
#include <vector>
#include <chrono>
#include <thread>

namespace hal_test {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

constexpr unsigned long kPeriod = 1000000;   // every first thread asks for 1 ms

struct Counter {
    std::atomic<int> calls{0};
    std::atomic<long> period{0};
};

void count_call(void* arg, long period)
{
    auto* c = static_cast<Counter*>(arg);
    c->period.store(period);
    c->calls.fetch_add(1);
}

void nothing(void*, long) {}

class HalFunct : public HalRt {
protected:
    void SetUp() override
    {
        HalRt::SetUp();
        for (const char* f : {"rt.a", "rt.b", "rt.c", "rt.d", "rt.e"})
            ASSERT_EQ(hal_export_funct(f, nothing, nullptr, 0, 0, comp_), 0);
        ASSERT_EQ(hal_export_funct("rt.fp", nothing, nullptr, 1, 0, comp_), 0);
        ASSERT_EQ(hal_export_funct("rt.re", nothing, nullptr, 0, 1, comp_), 0);
        ASSERT_EQ(new_thread("fast", kPeriod, 0), 0);
        ASSERT_EQ(new_thread("slow", 2 * kPeriod, 1), 0);
    }
};

// Runs 'pred' until it holds or 2 s have passed: the machine may be busy.
template <class Pred>
bool eventually(Pred pred)
{
    auto end = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (!pred()) {
        if (std::chrono::steady_clock::now() > end)
            return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
}

TEST_F(HalRt, ExportCreatesTheFunctionWithItsTimePinAndTmaxParameter)
{
    int x = 0;
    ASSERT_EQ(hal_export_funct("rt.update", nothing, &x, 1, 0, comp_), 0);
    auto* f = funct_rec("rt.update");
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->funct, reinterpret_cast<rtapi_u64>(&nothing));
    EXPECT_EQ(f->arg, reinterpret_cast<rtapi_u64>(&x));
    EXPECT_EQ(f->uses_fp, 1);
    EXPECT_EQ(f->reentrant, 0);
    EXPECT_EQ(f->users, 0);
    auto* time = pin_rec("rt.update.time");
    ASSERT_NE(time, nullptr);
    EXPECT_EQ(time->type, HAL_S32);
    EXPECT_EQ(time->dir, HAL_OUT);
    auto* tmax = param_rec("rt.update.tmax");
    ASSERT_NE(tmax, nullptr);
    EXPECT_EQ(tmax->type, HAL_S32);
    EXPECT_EQ(tmax->dir, HAL_RW);
}

TEST_F(HalRt, ExportRefusesNullCode)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_export_funct("rt.null", nullptr, nullptr, 0, 0, comp_), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("function 'rt.null': code address is NULL"));
    EXPECT_EQ(funct_rec("rt.null"), nullptr);
}

TEST_F(HalRt, ExportRefusesADuplicateAndKeepsTheOriginal)
{
    ASSERT_EQ(hal_export_funct("rt.f", nothing, nullptr, 0, 0, comp_), 0);
    EXPECT_EQ(hal_export_funct("rt.f", count_call, nullptr, 0, 0, comp_), -EEXIST);
    EXPECT_EQ(funct_rec("rt.f")->funct, reinterpret_cast<rtapi_u64>(&nothing));
    EXPECT_NE(pin_rec("rt.f.time"), nullptr);
    EXPECT_NE(param_rec("rt.f.tmax"), nullptr);
}

TEST_F(HalRt, ExportRefusesAnUnknownComponent)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_export_funct("rt.f", nothing, nullptr, 0, 0, 9999), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("function 'rt.f': component id 9999 does not exist"));
}

TEST_F(HalRt, ExportAcceptsA47CharacterNameWithItsTimingObjects)
{
    std::string name = "rt." + std::string(44, 'f');   // 47, as RULINGS.md promises
    ASSERT_EQ(hal_export_funct(name.c_str(), nothing, nullptr, 0, 0, comp_), 0);
    EXPECT_NE(pin_rec(name + ".time"), nullptr);
    EXPECT_NE(param_rec(name + ".tmax"), nullptr);
}

TEST_F(HalRt, ExportOfANameTooLongForItsTimingObjectsLeavesNothingBehind)
{
    rtapi_u32 used = hal_seg->bytes_used;
    std::string name = "rt." + std::string(HAL_NAME_LEN - 5, 'f');   // fits, "<name>.time" does not
    EXPECT_LT(hal_export_funct(name.c_str(), nothing, nullptr, 0, 0, comp_), 0);
    EXPECT_EQ(funct_rec(name), nullptr);
    EXPECT_EQ(hal_seg->bytes_used, used);
}

TEST_F(HalFunct, AddPlacesFunctionsByPosition)
{
    ASSERT_EQ(hal_add_funct_to_thread("rt.a", "fast", -1), 0);   // [a]
    ASSERT_EQ(hal_add_funct_to_thread("rt.b", "fast", 1), 0);    // [b a]
    ASSERT_EQ(hal_add_funct_to_thread("rt.c", "fast", -1), 0);   // [b a c]
    ASSERT_EQ(hal_add_funct_to_thread("rt.d", "fast", 2), 0);    // [b d a c]
    ASSERT_EQ(hal_add_funct_to_thread("rt.e", "fast", -2), 0);   // [b d a e c]
    EXPECT_THAT(thread_functs("fast"), ElementsAre("rt.b", "rt.d", "rt.a", "rt.e", "rt.c"));
    EXPECT_EQ(funct_rec("rt.a")->users, 1);
}

TEST_F(HalFunct, AddAcceptsThePositionJustPastTheEnd)
{
    ASSERT_EQ(hal_add_funct_to_thread("rt.a", "fast", 1), 0);
    ASSERT_EQ(hal_add_funct_to_thread("rt.b", "fast", 2), 0);
    EXPECT_THAT(thread_functs("fast"), ElementsAre("rt.a", "rt.b"));
}

TEST_F(HalFunct, AddRefusesPositionZeroAndPositionsPastEitherEnd)
{
    ASSERT_EQ(hal_add_funct_to_thread("rt.a", "fast", 1), 0);
    MsgCapture msgs;
    EXPECT_EQ(hal_add_funct_to_thread("rt.b", "fast", 0), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("position 0 is not valid for thread 'fast' with 1 functions"));
    EXPECT_EQ(hal_add_funct_to_thread("rt.b", "fast", 3), -EINVAL);
    EXPECT_EQ(hal_add_funct_to_thread("rt.b", "fast", -3), -EINVAL);
    EXPECT_THAT(thread_functs("fast"), ElementsAre("rt.a"));
    EXPECT_EQ(funct_rec("rt.b")->users, 0);
}

TEST_F(HalFunct, AddRefusesANonReentrantFunctionOnASecondThread)
{
    ASSERT_EQ(hal_add_funct_to_thread("rt.a", "fast", 1), 0);
    MsgCapture msgs;
    EXPECT_EQ(hal_add_funct_to_thread("rt.a", "slow", 1), -EBUSY);
    EXPECT_THAT(msgs.text(), HasSubstr("function 'rt.a' is already on a thread and is not reentrant"));
    EXPECT_EQ(hal_add_funct_to_thread("rt.a", "fast", 1), -EBUSY);
    EXPECT_TRUE(thread_functs("slow").empty());
}

TEST_F(HalFunct, AddAllowsAReentrantFunctionOnTwoThreads)
{
    ASSERT_EQ(hal_add_funct_to_thread("rt.re", "fast", 1), 0);
    ASSERT_EQ(hal_add_funct_to_thread("rt.re", "slow", 1), 0);
    EXPECT_EQ(funct_rec("rt.re")->users, 2);
}

TEST_F(HalFunct, AddRefusesAFloatingPointFunctionOnAThreadWithoutIt)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_add_funct_to_thread("rt.fp", "fast", 1), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("function 'rt.fp' uses floating point but thread 'fast'"));
    EXPECT_EQ(hal_add_funct_to_thread("rt.fp", "slow", 1), 0);
    EXPECT_EQ(hal_add_funct_to_thread("rt.a", "slow", 1), 0);   // no-FP code may run anywhere
}

TEST_F(HalFunct, AddRefusesAnUnknownFunctionOrThread)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_add_funct_to_thread("rt.nosuch", "fast", 1), -ENOENT);
    EXPECT_THAT(msgs.text(), HasSubstr("function 'rt.nosuch' does not exist"));
    EXPECT_EQ(hal_add_funct_to_thread("rt.a", "nosuch", 1), -ENOENT);
    EXPECT_THAT(msgs.text(), HasSubstr("thread 'nosuch' does not exist"));
}

TEST_F(HalFunct, DelRemovesTheFunctionFromTheThread)
{
    ASSERT_EQ(hal_add_funct_to_thread("rt.a", "fast", -1), 0);
    ASSERT_EQ(hal_add_funct_to_thread("rt.b", "fast", -1), 0);
    ASSERT_EQ(hal_add_funct_to_thread("rt.c", "fast", -1), 0);
    EXPECT_EQ(hal_del_funct_from_thread("rt.b", "fast"), 0);
    EXPECT_THAT(thread_functs("fast"), ElementsAre("rt.a", "rt.c"));
    EXPECT_EQ(funct_rec("rt.b")->users, 0);
    EXPECT_EQ(hal_add_funct_to_thread("rt.b", "slow", 1), 0);   // free to go elsewhere now
}

TEST_F(HalFunct, DelRefusesAFunctionThatIsNotOnTheThread)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_del_funct_from_thread("rt.a", "fast"), -ENOENT);
    EXPECT_THAT(msgs.text(), HasSubstr("function 'rt.a' is not on thread 'fast'"));
    EXPECT_EQ(hal_del_funct_from_thread("rt.nosuch", "fast"), -ENOENT);
    EXPECT_EQ(hal_del_funct_from_thread("rt.a", "nosuch"), -ENOENT);
}

// --- threads ---

TEST_F(HalRt, TheFirstThreadSetsTheBasePeriod)
{
    EXPECT_EQ(hal_seg->base_period_ns, 0);
    ASSERT_EQ(new_thread("t1", kPeriod, 0), 0);
    EXPECT_GT(hal_seg->base_period_ns, 0);
    EXPECT_EQ(thread_rec("t1")->period_ns, hal_seg->base_period_ns);
}

TEST_F(HalRt, LaterPeriodsAreRoundedToMultiplesOfTheBasePeriod)
{
    ASSERT_EQ(new_thread("t1", kPeriod, 0), 0);
    long long base = hal_seg->base_period_ns;
    ASSERT_EQ(new_thread("t2", static_cast<unsigned long>(base * 24 / 10), 0), 0);
    ASSERT_EQ(new_thread("t3", static_cast<unsigned long>(base * 26 / 10), 0), 0);
    ASSERT_EQ(new_thread("t4", static_cast<unsigned long>(base * 5), 0), 0);
    EXPECT_EQ(thread_rec("t2")->period_ns, 2 * base);
    EXPECT_EQ(thread_rec("t3")->period_ns, 3 * base);
    EXPECT_EQ(thread_rec("t4")->period_ns, 5 * base);
}

TEST_F(HalRt, SlowerThreadsGetLowerPriorities)
{
    ASSERT_EQ(new_thread("t1", kPeriod, 0), 0);
    ASSERT_EQ(new_thread("t2", 2 * kPeriod, 0), 0);
    EXPECT_EQ(thread_rec("t1")->priority, rtapi_prio_highest());
    EXPECT_EQ(thread_rec("t2")->priority, rtapi_prio_next_lower(rtapi_prio_highest()));
}

TEST_F(HalRt, AThreadFasterThanTheBasePeriodIsRefused)
{
    ASSERT_EQ(new_thread("t1", kPeriod, 0), 0);
    MsgCapture msgs;
    EXPECT_EQ(new_thread("t0", static_cast<unsigned long>(hal_seg->base_period_ns / 2), 0), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("thread 't0': period"));
    EXPECT_THAT(msgs.text(), HasSubstr("create the fastest thread first"));
    EXPECT_EQ(thread_rec("t0"), nullptr);
}

TEST_F(HalRt, APeriodUnderOneMicrosecondIsRefused)
{
    MsgCapture msgs;
    EXPECT_EQ(new_thread("t1", 999, 0), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("thread 't1': period 999 ns is too short"));
    EXPECT_EQ(hal_seg->base_period_ns, 0);
}

TEST_F(HalRt, ARefusedFirstThreadLeavesNoBasePeriod)
{
    EXPECT_EQ(new_thread("bad name", kPeriod, 0), -EINVAL);
    EXPECT_EQ(hal_seg->base_period_ns, 0);
}

TEST_F(HalRt, AFirstThreadOfALaterSessionPrintsNoClockError)
{
    ASSERT_EQ(new_thread("t1", kPeriod, 0), 0);   // the clock runs from here on
    ASSERT_EQ(hal_thread_delete("t1"), 0);
    MsgCapture msgs;
    ASSERT_EQ(new_thread("t1", kPeriod, 0), 0);
    EXPECT_EQ(msgs.text(), "");
    EXPECT_EQ(thread_rec("t1")->period_ns, kPeriod);
}

TEST_F(HalRt, ADuplicateThreadNameIsRefused)
{
    ASSERT_EQ(new_thread("t1", kPeriod, 0), 0);
    EXPECT_EQ(new_thread("t1", 2 * kPeriod, 0), -EEXIST);
    EXPECT_EQ(thread_rec("t1")->period_ns, hal_seg->base_period_ns);
}

TEST_F(HalRt, AThreadHasATimePinAndTmaxParameter)
{
    ASSERT_EQ(new_thread("t1", kPeriod, 1), 0);
    ASSERT_NE(pin_rec("t1.time"), nullptr);
    EXPECT_EQ(pin_rec("t1.time")->dir, HAL_OUT);
    ASSERT_NE(param_rec("t1.tmax"), nullptr);
    EXPECT_EQ(thread_rec("t1")->uses_fp, 1);
}

TEST_F(HalFunct, ThreadDeleteRemovesTheThreadItsTimingObjectsAndItsEntries)
{
    ASSERT_EQ(hal_add_funct_to_thread("rt.fp", "slow", 1), 0);
    ASSERT_EQ(hal_thread_delete("slow"), 0);
    EXPECT_EQ(thread_rec("slow"), nullptr);
    EXPECT_EQ(pin_rec("slow.time"), nullptr);
    EXPECT_EQ(param_rec("slow.tmax"), nullptr);
    EXPECT_EQ(funct_rec("rt.fp")->users, 0);
    MsgCapture msgs;
    EXPECT_EQ(hal_thread_delete("slow"), -ENOENT);
    EXPECT_THAT(msgs.text(), HasSubstr("thread 'slow' does not exist"));
}

TEST_F(HalFunct, DeletingTheLastThreadClearsTheBasePeriod)
{
    ASSERT_EQ(hal_thread_delete("slow"), 0);
    EXPECT_GT(hal_seg->base_period_ns, 0);
    ASSERT_EQ(hal_thread_delete("fast"), 0);
    EXPECT_EQ(hal_seg->base_period_ns, 0);
}

TEST_F(HalRt, AStartedThreadCallsItsFunctionsWithArgumentAndPeriod)
{
    Counter c;
    ASSERT_EQ(hal_export_funct("rt.count", count_call, &c, 0, 0, comp_), 0);
    ASSERT_EQ(new_thread("t1", kPeriod, 0), 0);
    ASSERT_EQ(hal_add_funct_to_thread("rt.count", "t1", 1), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_EQ(c.calls.load(), 0) << "threads run only after hal_start_threads";

    auto start = std::chrono::steady_clock::now();
    ASSERT_EQ(hal_start_threads(), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_TRUE(eventually([&] { return c.calls.load() >= 5; })) << c.calls.load() << " calls";
    ASSERT_EQ(hal_stop_threads(), 0);
    auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start).count();
    long long period_ms = thread_rec("t1")->period_ns / 1000000;
    EXPECT_LE(c.calls.load(), ms / (period_ms ? period_ms : 1) + 10) << "after " << ms << " ms";
    EXPECT_EQ(c.period.load(), thread_rec("t1")->period_ns);
    EXPECT_GE(thread_rt("t1")->cycles, static_cast<rtapi_u64>(c.calls.load()));
}

TEST_F(HalRt, StopThreadsStopsTheCalls)
{
    Counter c;
    ASSERT_EQ(hal_export_funct("rt.count", count_call, &c, 0, 0, comp_), 0);
    ASSERT_EQ(new_thread("t1", kPeriod, 0), 0);
    ASSERT_EQ(hal_add_funct_to_thread("rt.count", "t1", 1), 0);
    ASSERT_EQ(hal_start_threads(), 0);
    ASSERT_TRUE(eventually([&] { return c.calls.load() >= 2; }));
    ASSERT_EQ(hal_stop_threads(), 0);
    int after_stop = c.calls.load();
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    EXPECT_EQ(c.calls.load(), after_stop);
}

TEST_F(HalRt, FunctionsRunInThreadOrderEveryCycle)
{
    static std::atomic<int> seq{0};
    struct Stamp {
        std::atomic<int> last{-1};
    } first, second;
    auto stamp = [](void* arg, long) { static_cast<Stamp*>(arg)->last.store(seq.fetch_add(1)); };
    ASSERT_EQ(hal_export_funct("rt.first", stamp, &first, 0, 0, comp_), 0);
    ASSERT_EQ(hal_export_funct("rt.second", stamp, &second, 0, 0, comp_), 0);
    ASSERT_EQ(new_thread("t1", kPeriod, 0), 0);
    ASSERT_EQ(hal_add_funct_to_thread("rt.second", "t1", 1), 0);
    ASSERT_EQ(hal_add_funct_to_thread("rt.first", "t1", 1), 0);
    ASSERT_EQ(hal_start_threads(), 0);
    ASSERT_TRUE(eventually([&] { return second.last.load() >= 0; }));
    ASSERT_EQ(hal_stop_threads(), 0);
    EXPECT_EQ(second.last.load(), first.last.load() + 1);
}

TEST_F(HalRt, ExitOfAComponentWhileThreadsRunTakesItsFunctionOffOtherThreads)
{
    Counter mine, theirs;
    ASSERT_EQ(hal_export_funct("rt.count", count_call, &mine, 0, 0, comp_), 0);
    ASSERT_EQ(new_thread("t1", kPeriod, 0), 0);
    ASSERT_EQ(hal_add_funct_to_thread("rt.count", "t1", 1), 0);
    int other = hal_init("rt.other");
    ASSERT_GT(other, 0);
    ASSERT_EQ(hal_export_funct("rt.other.count", count_call, &theirs, 0, 0, other), 0);
    ASSERT_EQ(hal_add_funct_to_thread("rt.other.count", "t1", -1), 0);
    ASSERT_EQ(hal_start_threads(), 0);
    ASSERT_TRUE(eventually([&] { return theirs.calls.load() >= 2; }));

    ASSERT_EQ(hal_exit(other), 0);
    int frozen = theirs.calls.load();
    int before = mine.calls.load();
    EXPECT_TRUE(eventually([&] { return mine.calls.load() >= before + 3; }));
    EXPECT_EQ(theirs.calls.load(), frozen);
    EXPECT_THAT(thread_functs("t1"), ElementsAre("rt.count"));
}

// Dispatch tables (issue 20): the thread runs an array rebuilt on addf/delf while it runs.
struct Guarded {
    std::atomic<bool> removed{false};   // set once delf returned
    std::atomic<int> calls{0};
    std::atomic<int> late{0};            // calls after delf returned: must stay 0
};

void guarded_call(void* arg, long)
{
    auto* g = static_cast<Guarded*>(arg);
    if (g->removed.load())
        g->late.fetch_add(1);
    g->calls.fetch_add(1);
}

TEST_F(HalRt, AddWhileRunningIsCalledFromTheNextCycles)
{
    Counter c;
    ASSERT_EQ(hal_export_funct("rt.count", count_call, &c, 0, 0, comp_), 0);
    ASSERT_EQ(hal_export_funct("rt.idle", nothing, nullptr, 0, 0, comp_), 0);
    ASSERT_EQ(new_thread("t1", kPeriod, 0), 0);
    ASSERT_EQ(hal_add_funct_to_thread("rt.idle", "t1", 1), 0);
    ASSERT_EQ(hal_start_threads(), 0);
    ASSERT_EQ(hal_add_funct_to_thread("rt.count", "t1", 1), 0);   // in front: a new table
    EXPECT_TRUE(eventually([&] { return c.calls.load() >= 3; }));
    ASSERT_EQ(hal_stop_threads(), 0);
    EXPECT_THAT(thread_functs("t1"), ElementsAre("rt.count", "rt.idle"));
}

TEST_F(HalRt, DelWhileRunningReturnsOnlyWhenNoCallCanFollow)
{
    ASSERT_EQ(new_thread("t1", kPeriod, 0), 0);
    std::vector<std::unique_ptr<Guarded>> g;
    // More functions than a first table holds: appends also grow it while running.
    for (int i = 0; i < 40; i++) {
        g.push_back(std::make_unique<Guarded>());
        std::string name = "rt.g" + std::to_string(i);
        ASSERT_EQ(hal_export_funct(name.c_str(), guarded_call, g.back().get(), 0, 0, comp_), 0);
    }
    ASSERT_EQ(hal_start_threads(), 0);
    for (int i = 0; i < 40; i++) {
        std::string name = "rt.g" + std::to_string(i);
        int pos = i % 3 == 0 ? 1 : i % 3 == 1 ? -1 : 2;   // first, last, second
        ASSERT_EQ(hal_add_funct_to_thread(name.c_str(), "t1", pos), 0) << name;
    }
    EXPECT_EQ(thread_functs("t1").size(), 40u);
    ASSERT_TRUE(eventually([&] { return g[39]->calls.load() >= 2; }));
    for (int i = 0; i < 40; i += 2) {   // every other one, while the others keep running
        std::string name = "rt.g" + std::to_string(i);
        ASSERT_EQ(hal_del_funct_from_thread(name.c_str(), "t1"), 0) << name;
        g[i]->removed.store(true);
    }
    int before = g[1]->calls.load();
    EXPECT_TRUE(eventually([&] { return g[1]->calls.load() >= before + 3; }));
    ASSERT_EQ(hal_stop_threads(), 0);
    for (int i = 0; i < 40; i++) {
        EXPECT_EQ(g[i]->late.load(), 0) << "rt.g" << i << " was called after its delf returned";
        EXPECT_GT(g[i]->calls.load(), 0) << "rt.g" << i;
    }
    std::vector<std::string> left = thread_functs("t1");
    EXPECT_EQ(left.size(), 20u);
    for (const std::string& n : left)
        EXPECT_EQ(std::stoi(n.substr(4)) % 2, 1) << n;
}

TEST_F(HalRt, FunctionAndThreadTimingIsKeptByTheDispatchLoop)
{
    Counter c;
    ASSERT_EQ(hal_export_funct("rt.count", count_call, &c, 0, 0, comp_), 0);
    ASSERT_EQ(hal_export_funct("rt.idle", nothing, nullptr, 0, 0, comp_), 0);
    ASSERT_EQ(new_thread("t1", kPeriod, 0), 0);
    ASSERT_EQ(hal_add_funct_to_thread("rt.count", "t1", -1), 0);
    ASSERT_EQ(hal_add_funct_to_thread("rt.idle", "t1", -1), 0);
    ASSERT_EQ(hal_start_threads(), 0);
    ASSERT_TRUE(eventually([&] { return thread_rt("t1")->cycles >= 3; }));
    ASSERT_EQ(hal_stop_threads(), 0);
    // Clocks are never 0 across a call; the thread's time covers both functions.
    EXPECT_GT(funct_rec("rt.count")->tmax, 0);
    EXPECT_GT(funct_rec("rt.idle")->tmax, 0);
    EXPECT_GE(thread_rt("t1")->tmax, funct_rec("rt.count")->tmax);
    EXPECT_GT(*thread_rec("t1")->time_ptr, 0);
    EXPECT_GT(*funct_rec("rt.idle")->time_ptr, 0);
    EXPECT_EQ(seg_ptr(param_rec("t1.tmax")->data_off), &thread_rt("t1")->tmax);   // the parameter is it
}

}  // namespace
}  // namespace hal_test
