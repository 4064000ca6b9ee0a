// SPDX-License-Identifier: GPL-2.0-or-later
// rtapi_shmem_test - POSIX shared memory blocks: creation, sharing between modules and
// processes, the reference count that unlinks on the last delete, and every refusal.
// Each test program uses its own RTAPI_INSTANCE so parallel runs never meet.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rtapi.h"
#include "rtapi_shmem_uspace.h"

namespace {

std::vector<std::string> messages;

void capture(msg_level_t, const char* msg)
{
    messages.emplace_back(msg);
}

class RtapiShmem : public ::testing::Test {
protected:
    void SetUp() override
    {
        instance_ = "utest-shmem-" + std::to_string(getpid());
        setenv("RTAPI_INSTANCE", instance_.c_str(), 1);
        messages.clear();
        rtapi_set_msg_handler(capture);
        mod_a_ = rtapi_init("shm_a");
        mod_b_ = rtapi_init("shm_b");
        ASSERT_GT(mod_a_, 0);
        ASSERT_GT(mod_b_, 0);
    }
    void TearDown() override
    {
        rtapi_exit(mod_a_);
        rtapi_exit(mod_b_);
        rtapi_shmem_force_unlink_all();
        rtapi_set_msg_handler(nullptr);
    }
    bool exists(int key) const
    {
        char path[128];
        std::snprintf(path, sizeof path, "/dev/shm/rtapi-%u-%s-%08x", (unsigned)getuid(), instance_.c_str(),
                      (unsigned)key);
        return access(path, F_OK) == 0;
    }
    std::string instance_;
    int mod_a_ = 0, mod_b_ = 0;
};

TEST_F(RtapiShmem, NewBlockIsZeroedAndNamedByUidInstanceAndKey)
{
    int id = rtapi_shmem_new(0x1234, mod_a_, 100);
    ASSERT_GT(id, 0);
    EXPECT_TRUE(exists(0x1234));
    void* p = nullptr;
    ASSERT_EQ(rtapi_shmem_getptr(id, &p), 0);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(*static_cast<volatile unsigned*>(p), 0u);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(p) % 4096, 0u);
    EXPECT_EQ(rtapi_shmem_delete(id, mod_a_), 0);
    EXPECT_FALSE(exists(0x1234));
}

TEST_F(RtapiShmem, ModulesShareOneMappingAndTheLastDeleteUnlinks)
{
    int a = rtapi_shmem_new(0x42, mod_a_, 4096);
    ASSERT_GT(a, 0);
    void *pa, *pb;
    rtapi_shmem_getptr(a, &pa);
    static_cast<int*>(pa)[0] = 77;
    int b = rtapi_shmem_new(0x42, mod_b_, 1000);  // smaller is fine
    EXPECT_EQ(b, a);
    rtapi_shmem_getptr(b, &pb);
    EXPECT_EQ(pb, pa);
    EXPECT_EQ(static_cast<int*>(pb)[0], 77);
    EXPECT_EQ(rtapi_shmem_new(0x42, mod_a_, 4096), a);  // asking again changes nothing
    EXPECT_EQ(rtapi_shmem_delete(a, mod_a_), 0);
    EXPECT_TRUE(exists(0x42));
    EXPECT_EQ(rtapi_shmem_getptr(b, &pb), 0);
    EXPECT_EQ(static_cast<int*>(pb)[0], 77);
    EXPECT_EQ(rtapi_shmem_delete(b, mod_b_), 0);
    EXPECT_FALSE(exists(0x42));
    EXPECT_EQ(rtapi_shmem_getptr(b, &pb), -EINVAL);
}

TEST_F(RtapiShmem, OtherProcessesSeeTheSameBlockAndHoldReferences)
{
    int id = rtapi_shmem_new(0x77, mod_a_, 64);
    ASSERT_GT(id, 0);
    void* p;
    rtapi_shmem_getptr(id, &p);
    static_cast<volatile int*>(p)[0] = 1;
    pid_t child = fork();
    if (child == 0) {  // attach, check, write, detach: the block must survive
        int mod = rtapi_init("child");
        int cid = rtapi_shmem_new(0x77, mod, 64);
        void* cp;
        if (cid <= 0 || rtapi_shmem_getptr(cid, &cp) != 0 || static_cast<volatile int*>(cp)[0] != 1)
            _exit(2);
        static_cast<volatile int*>(cp)[1] = 99;
        _exit(rtapi_exit(mod) == 0 ? 0 : 3);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    EXPECT_EQ(static_cast<volatile int*>(p)[1], 99);
    EXPECT_TRUE(exists(0x77));
    EXPECT_EQ(rtapi_shmem_delete(id, mod_a_), 0);
    EXPECT_FALSE(exists(0x77));
}

TEST_F(RtapiShmem, BlockOutlivesItsCreatorProcess)
{
    pid_t child = fork();
    if (child == 0) {  // create and keep it (a second module stays attached), then exit
        int mod = rtapi_init("creator");
        int id = rtapi_shmem_new(0x99, mod, 64);
        void* cp;
        rtapi_shmem_getptr(id, &cp);
        static_cast<int*>(cp)[0] = 5;
        _exit(id > 0 ? 0 : 1);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_EQ(WEXITSTATUS(status), 0);
    int id = rtapi_shmem_new(0x99, mod_a_, 64);
    ASSERT_GT(id, 0);
    void* p;
    rtapi_shmem_getptr(id, &p);
    EXPECT_EQ(static_cast<int*>(p)[0], 5);  // not zeroed again
    EXPECT_EQ(rtapi_shmem_delete(id, mod_a_), 0);
    EXPECT_TRUE(exists(0x99));  // the dead creator's reference remains: halrun -U cleans it
    EXPECT_EQ(rtapi_shmem_force_unlink_all(), 1);
    EXPECT_FALSE(exists(0x99));
}

TEST_F(RtapiShmem, OpeningWithALargerSizeIsRefused)
{
    int id = rtapi_shmem_new(0x55, mod_a_, 100);
    ASSERT_GT(id, 0);
    EXPECT_EQ(rtapi_shmem_new(0x55, mod_b_, 200), -EINVAL);
    ASSERT_FALSE(messages.empty());
    EXPECT_EQ(messages.back(), "rtapi: shared memory key 0x00000055 has 100 bytes, 200 requested\n");
    pid_t child = fork();
    if (child == 0) {  // a process without the mapping reads the size from the header
        messages.clear();
        int mod = rtapi_init("child");
        int r = rtapi_shmem_new(0x55, mod, 200);
        bool ok = r == -EINVAL && !messages.empty() &&
                  messages.back() == "rtapi: shared memory key 0x00000055 has 100 bytes, 200 requested\n";
        _exit(ok ? 0 : 1);
    }
    int status = 0;
    waitpid(child, &status, 0);
    EXPECT_EQ(WEXITSTATUS(status), 0);
    EXPECT_EQ(rtapi_shmem_delete(id, mod_a_), 0);
    EXPECT_FALSE(exists(0x55));
}

TEST_F(RtapiShmem, BadArgumentsAreRefusedWithAMessage)
{
    EXPECT_EQ(rtapi_shmem_new(0, mod_a_, 100), -EINVAL);
    EXPECT_EQ(messages.back(), "rtapi: rtapi_shmem_new(key 0x00000000, 100 bytes): the key must be nonzero "
                               "and the size 1..2^40\n");
    EXPECT_EQ(rtapi_shmem_new(1, mod_a_, 0), -EINVAL);
    EXPECT_EQ(rtapi_shmem_new(1, 999, 10), -EINVAL);
    EXPECT_EQ(messages.back(), "rtapi: rtapi_shmem_new(key 0x00000001): module 999 did not come from rtapi_init\n");
    EXPECT_EQ(rtapi_shmem_delete(31, mod_a_), -EINVAL);
    EXPECT_EQ(messages.back(), "rtapi: rtapi_shmem_delete(31, module " + std::to_string(mod_a_) +
                                   "): the module does not hold that block\n");
    int id = rtapi_shmem_new(0x66, mod_a_, 10);
    ASSERT_GT(id, 0);
    EXPECT_EQ(rtapi_shmem_delete(id, mod_b_), -EINVAL);  // b never asked for it
    void* p;
    EXPECT_EQ(rtapi_shmem_getptr(0, &p), -EINVAL);
    EXPECT_EQ(rtapi_shmem_getptr(id, nullptr), -EINVAL);
    EXPECT_EQ(rtapi_shmem_delete(id, mod_a_), 0);
}

TEST_F(RtapiShmem, RtapiExitDetachesWhatTheModuleForgot)
{
    int mod = rtapi_init("forgetful");
    ASSERT_GT(rtapi_shmem_new(0x101, mod, 10), 0);
    ASSERT_GT(rtapi_shmem_new(0x102, mod, 10), 0);
    EXPECT_TRUE(exists(0x101));
    EXPECT_EQ(rtapi_exit(mod), 0);
    EXPECT_FALSE(exists(0x101));
    EXPECT_FALSE(exists(0x102));
}

TEST_F(RtapiShmem, ForceUnlinkRemovesOnlyThisInstance)
{
    int id = rtapi_shmem_new(0x201, mod_a_, 10);
    ASSERT_GT(id, 0);
    setenv("RTAPI_INSTANCE", (instance_ + "x").c_str(), 1);
    EXPECT_EQ(rtapi_shmem_force_unlink_all(), 0);  // another instance: nothing of ours
    setenv("RTAPI_INSTANCE", instance_.c_str(), 1);
    EXPECT_TRUE(exists(0x201));
    EXPECT_EQ(rtapi_shmem_force_unlink_all(), 1);
    EXPECT_FALSE(exists(0x201));
    EXPECT_EQ(rtapi_shmem_delete(id, mod_a_), 0);  // the mapping was still ours to drop
}

TEST_F(RtapiShmem, InstanceNamesWithSlashesAreRefused)
{
    setenv("RTAPI_INSTANCE", "a/b", 1);
    EXPECT_EQ(rtapi_shmem_new(0x301, mod_a_, 10), -EINVAL);
    EXPECT_EQ(messages.back(), "rtapi: RTAPI_INSTANCE='a/b' is not usable: at most 32 characters, no '/'\n");
    setenv("RTAPI_INSTANCE", instance_.c_str(), 1);
}

}  // namespace
