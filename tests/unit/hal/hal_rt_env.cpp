// SPDX-License-Identifier: GPL-2.0-or-later
// hal_rt_env.cpp - main() and fixture of hal_api_rt_test: a private RTAPI instance,
// the anchor component, and a check that the segment is gone at the end.
#include "hal_rt_fixture.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace hal_test {
namespace {

std::string g_instance;
int g_anchor = 0;

class HalRtEnv : public ::testing::Environment {
public:
    void SetUp() override { restore_anchor(); }
    void TearDown() override
    {
        drop_anchor();
        EXPECT_EQ(hal_seg, nullptr) << "a test left a component behind";
        if (std::filesystem::exists(hal_shm_path())) {
            ADD_FAILURE() << hal_shm_path() << " still exists after the last component exited";
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

void drop_anchor()
{
    if (g_anchor > 0)
        hal_exit(g_anchor);
    g_anchor = 0;
}

void restore_anchor()
{
    g_anchor = hal_init("anchor");
    ASSERT_GT(g_anchor, 0);
}

std::vector<std::string> thread_functs(const std::string& thread)
{
    std::vector<std::string> out;
    auto* t = thread_rec(thread);
    if (!t)
        return out;
    for (rtapi_u32 off = t->first_entry_off; off;) {
        auto* e = static_cast<struct hal_entry_rec*>(seg_ptr(off));
        out.emplace_back(static_cast<struct hal_obj_hdr*>(seg_ptr(e->funct_off))->name);
        off = e->next_off;
    }
    return out;
}

void HalRt::SetUp()
{
    comp_ = hal_init("rt");
    ASSERT_GT(comp_, 0);
    pins_ = mem<PinPtrs>();
    ASSERT_NE(pins_, nullptr);
}

void HalRt::TearDown()
{
    hal_set_lock(HAL_LOCK_NONE);
    hal_stop_threads();
    for (const auto& s : sigs_)
        hal_signal_delete(s.c_str());
    hal_exit_threads();  // threads outlive components (threads(9)); the host removes them
    if (comp_ > 0) {
        EXPECT_EQ(hal_exit(comp_), 0);
    }
}

int HalRt::new_signal(const std::string& name, hal_type_t type)
{
    int rc = hal_signal_new(name.c_str(), type);
    if (rc == 0)
        sigs_.push_back(name);
    return rc;
}

int HalRt::new_thread(const std::string& name, unsigned long period_ns, int uses_fp)
{
    return hal_create_thread(name.c_str(), period_ns, uses_fp);
}

}  // namespace hal_test

int main(int argc, char** argv)
{
    ::testing::InitGoogleMock(&argc, argv);
    hal_test::g_instance = "unit-hal-rt-" + std::to_string(getpid());
    setenv("RTAPI_INSTANCE", hal_test::g_instance.c_str(), 1);
    ::testing::AddGlobalTestEnvironment(new hal_test::HalRtEnv);
    return RUN_ALL_TESTS();
}
