// SPDX-License-Identifier: GPL-2.0-or-later
// hal_rthost_ul_test.cpp - a userspace tool and a realtime host in two processes,
// each with its own mapping of the segment: the tool sees the host's functions and
// threads, and links/sets made by the tool reach the host through its own pointers.
#include "hal_ul_fixture.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <thread>

namespace hal_test {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// The helper process, talked to line by line over two pipes.
class RtHost {
public:
    bool start()
    {
        int to[2], from[2];
        if (pipe(to) || pipe(from))
            return false;
        pid_ = fork();
        if (pid_ == 0) {
            dup2(to[0], 0);
            dup2(from[1], 1);
            close(to[1]);
            close(from[0]);
            execl(HAL_RT_HOST, HAL_RT_HOST, static_cast<char*>(nullptr));
            _exit(127);
        }
        close(to[0]);
        close(from[1]);
        in_ = fdopen(to[1], "w");
        out_ = fdopen(from[0], "r");
        return pid_ > 0 && in_ && out_ && line() == "ready";
    }
    std::string ask(const char* cmd)
    {
        std::fprintf(in_, "%s\n", cmd);
        std::fflush(in_);
        return line();
    }
    // The helper's wait status; stopping again returns the same.
    int stop()
    {
        if (pid_ <= 0)
            return status_;
        if (ask("quit") != "bye")
            kill(pid_, SIGKILL);
        std::fclose(in_);
        std::fclose(out_);
        waitpid(pid_, &status_, 0);
        pid_ = 0;
        return status_;
    }
    ~RtHost() { stop(); }

private:
    std::string line()
    {
        char buf[128];
        if (!std::fgets(buf, sizeof(buf), out_))
            return "";
        std::string s(buf);
        if (!s.empty() && s.back() == '\n')
            s.pop_back();
        return s;
    }

    pid_t pid_ = 0;
    int status_ = -1;
    FILE* in_ = nullptr;
    FILE* out_ = nullptr;
};

class HalRtHost : public HalUl {
protected:
    void SetUp() override
    {
        HalUl::SetUp();
        ASSERT_TRUE(host_.start()) << "cannot start " << HAL_RT_HOST;
    }
    void TearDown() override
    {
        hal_stop_threads();
        EXPECT_EQ(host_.stop(), 0);
        HalUl::TearDown();
    }
    RtHost host_;
};

TEST_F(HalRtHost, TheToolSeesTheRealtimeComponent)
{
    struct hal_comp_info c;
    ASSERT_EQ(hal_find_comp("rthost", &c), 0);
    EXPECT_TRUE(c.is_realtime);
    EXPECT_EQ(c.pid, 0);
    EXPECT_TRUE(c.is_ready);
}

TEST_F(HalRtHost, TheToolSeesFunctionsAndThreads)
{
    struct hal_funct_info f;
    ASSERT_EQ(hal_find_funct("rthost.update", &f), 0);
    EXPECT_STREQ(f.owner, "rthost");
    EXPECT_TRUE(f.uses_fp);
    EXPECT_FALSE(f.reentrant);
    EXPECT_EQ(f.users, 1);
    struct hal_thread_info t;
    ASSERT_EQ(hal_find_thread("rthost.thread", &t), 0);
    EXPECT_EQ(t.period_ns, hal_base_period());
    EXPECT_GT(t.period_ns, 0);
    EXPECT_TRUE(t.uses_fp);
    std::vector<std::string> functs;
    EXPECT_EQ(hal_query_thread_functs("rthost.thread",
                                      [](const char* n, void* ctx) {
                                          static_cast<std::vector<std::string>*>(ctx)->push_back(n);
                                          return 0;
                                      },
                                      &functs),
              1);
    EXPECT_THAT(functs, ElementsAre("rthost.update"));
    std::vector<hal_funct_info> all_f;
    std::vector<hal_thread_info> all_t;
    EXPECT_EQ(hal_query_functs(collect<hal_funct_info>, &all_f), 1);
    EXPECT_EQ(hal_query_threads(collect<hal_thread_info>, &all_t), 1);
    struct hal_pin_info time;
    EXPECT_EQ(hal_find_pin("rthost.update.time", &time), 0);
    struct hal_param_info tmax;
    EXPECT_EQ(hal_find_param("rthost.thread.tmax", &tmax), 0);
}

TEST_F(HalRtHost, ALinkMadeByTheToolAimsTheOwnersPointer)
{
    ASSERT_EQ(new_signal("ul.x", HAL_FLOAT), 0);
    ASSERT_EQ(hal_link("rthost.in", "ul.x"), 0);
    union hal_value v = {};
    v.f = 6.5;
    ASSERT_EQ(hal_set_sig_value("ul.x", &v), 0);
    EXPECT_EQ(host_.ask("in"), "6.5");
    ASSERT_EQ(hal_unlink("rthost.in"), 0);
    EXPECT_EQ(host_.ask("in"), "6.5") << "an unlinked pin keeps the last value";
    v.f = -1.0;
    ASSERT_EQ(hal_set_pin_value("rthost.in", &v), 0);
    EXPECT_EQ(host_.ask("in"), "-1");
}

TEST_F(HalRtHost, ASetParameterReachesTheRealtimeOwner)
{
    union hal_value v = {};
    v.f = 2.25;
    ASSERT_EQ(hal_set_param_value("rthost.gain", &v), 0);
    EXPECT_EQ(host_.ask("gain"), "2.25");
    EXPECT_EQ(hal_set_param_value("rthost.ro", &v), -EPERM);
}

TEST_F(HalRtHost, TheToolCannotRemoveRealtimeObjects)
{
    struct hal_comp_info c;
    ASSERT_EQ(hal_find_comp("rthost", &c), 0);
    MsgCapture msgs;
    EXPECT_EQ(hal_exit(c.id), -EPERM);
    EXPECT_THAT(msgs.text(), HasSubstr("component 'rthost' is realtime: unload it with unloadrt"));
    EXPECT_EQ(hal_thread_delete("rthost.thread"), -EPERM);
    EXPECT_THAT(msgs.text(), HasSubstr("thread 'rthost.thread' belongs to the realtime host"));
    EXPECT_EQ(hal_find_comp("rthost", &c), 0);
}

TEST_F(HalRtHost, ThreadsStartedByTheToolRunTheHostsFunctions)
{
    ASSERT_EQ(hal_start_threads(), 0);
    EXPECT_TRUE(hal_threads_running());
    struct hal_thread_info t = {};
    auto end = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (std::chrono::steady_clock::now() < end) {
        ASSERT_EQ(hal_find_thread("rthost.thread", &t), 0);
        if (t.cycles >= 3)
            break;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    EXPECT_GE(t.cycles, 3u);
    union hal_value v = {};
    v.f = 1.0;
    ASSERT_EQ(hal_set_pin_value("rthost.in", &v), 0);
    struct hal_pin_info out = {};
    end = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (std::chrono::steady_clock::now() < end && !out.value.b) {
        ASSERT_EQ(hal_find_pin("rthost.out", &out), 0);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    EXPECT_TRUE(out.value.b) << "rthost.update copies in > 0 to out";
    ASSERT_EQ(hal_stop_threads(), 0);
    EXPECT_FALSE(hal_threads_running());
}

TEST_F(HalRtHost, WhenTheHostExitsItsObjectsAreGone)
{
    EXPECT_EQ(host_.stop(), 0);
    struct hal_comp_info c;
    struct hal_funct_info f;
    struct hal_pin_info p;
    EXPECT_EQ(hal_find_comp("rthost", &c), -ENOENT);
    EXPECT_EQ(hal_find_funct("rthost.update", &f), -ENOENT);
    EXPECT_EQ(hal_find_pin("rthost.thread.time", &p), -ENOENT);
    EXPECT_EQ(hal_base_period(), 0);
}

}  // namespace
}  // namespace hal_test
