// SPDX-License-Identifier: GPL-2.0-or-later
// Lock file names and contents (ini-and-launch.md 3.1, 3.2 step 4).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <cstdlib>
#include <fstream>

#include "lockfile.hpp"

using namespace hal::launcher;

namespace {

struct Env {
    Env(const char* name, const char* value) : name_(name)
    {
        if (const char* old = std::getenv(name))
            old_ = old, had_ = true;
        if (value)
            setenv(name, value, 1);
        else
            unsetenv(name);
    }
    ~Env()
    {
        if (had_)
            setenv(name_, old_.c_str(), 1);
        else
            unsetenv(name_);
    }
    const char* name_;
    std::string old_;
    bool had_ = false;
};

}  // namespace

TEST(LockFile, NamesByProgramAndInstance)
{
    Env a("EMC_LOCK_FILE", nullptr), b("RTAPI_INSTANCE", nullptr), c("HAL_FLAVOR", nullptr);
    EXPECT_EQ(lock_path("emc"), "/tmp/emc.lock");
    EXPECT_EQ(lock_path("linuxcnc"), "/tmp/linuxcnc.lock");
    setenv("RTAPI_INSTANCE", "7", 1);
    EXPECT_EQ(lock_path("emc"), "/tmp/emc.lock.7");
    setenv("HAL_FLAVOR", "kernel", 1);                 // one HAL per machine there
    EXPECT_EQ(lock_path("emc"), "/tmp/emc.lock");
    setenv("EMC_LOCK_FILE", "/x/y.lock", 1);
    EXPECT_EQ(lock_path("emc"), "/x/y.lock");
}

TEST(LockFile, CreateHoldsOurPidAndRefusesASecond)
{
    std::string p = "/tmp/launcher_lock_test_" + std::to_string(getpid());
    unlink(p.c_str());
    ASSERT_TRUE(lock_create(p));
    EXPECT_EQ(lock_owner(p), getpid());
    EXPECT_TRUE(is_launcher(getpid()));
    auto again = lock_create(p);
    ASSERT_FALSE(again);
    EXPECT_NE(again.error().message.find("cannot create lock file " + p), std::string::npos);
    lock_remove(p);
    EXPECT_EQ(lock_owner(p), 0);
    std::ofstream(p) << "garbage\n";
    EXPECT_EQ(lock_owner(p), 0);
    lock_remove(p);
}

TEST(LockFile, AnotherProgramIsNotALauncher)
{
    pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        execl("/bin/sleep", "sleep", "5", static_cast<char*>(nullptr));
        _exit(127);
    }
    // the child runs our test binary until it has exec'd sleep
    for (int i = 0; i < 500 && is_launcher(child); i++)
        usleep(10000);
    EXPECT_FALSE(is_launcher(child));
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
}
