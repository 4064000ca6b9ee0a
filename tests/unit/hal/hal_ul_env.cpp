// SPDX-License-Identifier: GPL-2.0-or-later
// hal_ul_env.cpp - main() of hal_query_ul_test: a private RTAPI instance, attached
// for the whole run like halcmd, and a check that the segment is gone at the end.
#include "hal_ul_fixture.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace hal_test {
namespace {

std::string g_instance;

class HalUlEnv : public ::testing::Environment {
public:
    void SetUp() override { ASSERT_EQ(hal_attach(), 0); }
    void TearDown() override
    {
        hal_detach();
        EXPECT_EQ(hal_seg, nullptr) << "a test left a component behind";
        if (std::filesystem::exists(hal_shm_path())) {
            ADD_FAILURE() << hal_shm_path() << " still exists after detaching";
            shm_unlink(hal_shm_path().c_str() + std::string("/dev/shm").size());
        }
    }
};

}  // namespace

std::string hal_shm_path()
{
    char buf[256];
    std::snprintf(buf, sizeof(buf), "/dev/shm/rtapi-%u-%s-%08x", static_cast<unsigned>(getuid()),
                  g_instance.c_str(), static_cast<unsigned>(HAL_KEY));
    return buf;
}

}  // namespace hal_test

int main(int argc, char** argv)
{
    ::testing::InitGoogleMock(&argc, argv);
    hal_test::g_instance = "unit-hal-ul-" + std::to_string(getpid());
    setenv("RTAPI_INSTANCE", hal_test::g_instance.c_str(), 1);
    ::testing::AddGlobalTestEnvironment(new hal_test::HalUlEnv);
    return RUN_ALL_TESTS();
}
