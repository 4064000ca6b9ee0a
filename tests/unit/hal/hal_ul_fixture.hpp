// SPDX-License-Identifier: GPL-2.0-or-later
// hal_ul_fixture.hpp - shared by the hal_query_ul_test sources: a userspace
// component per test, and collecting query results.
#pragma once
#include <gtest/gtest.h>
#include <gmock/gmock.h>

#include <string>
#include <vector>

#include "hal.h"
#include "hal_query.h"
#include "hal_test_internal.h"
#include "msg_capture.hpp"

namespace hal_test {

std::string hal_shm_path();

// hal_query_* callback: copy every record into a std::vector<Info>.
template <class Info>
int collect(const Info* info, void* ctx)
{
    static_cast<std::vector<Info>*>(ctx)->push_back(*info);
    return 0;
}

template <class Info>
const Info* by_name(const std::vector<Info>& v, const std::string& name)
{
    for (const auto& i : v)
        if (name == i.name)
            return &i;
    return nullptr;
}

struct UlPins {
    hal_float_t* f[4];
    hal_bit_t* b[4];
    hal_s32_t* s[4];
    hal_u32_t* u[4];
    hal_float_t gain;
    hal_float_t ro;
};

class HalUl : public ::testing::Test {
protected:
    void SetUp() override
    {
        comp_ = hal_init("ul");
        ASSERT_GT(comp_, 0);
        p_ = static_cast<UlPins*>(hal_malloc(sizeof(UlPins)));
        ASSERT_NE(p_, nullptr);
    }
    void TearDown() override
    {
        hal_set_lock(HAL_LOCK_NONE);
        for (const auto& s : sigs_)
            hal_signal_delete(s.c_str());
        if (comp_ > 0) {
            EXPECT_EQ(hal_exit(comp_), 0);
        }
    }
    int new_signal(const std::string& name, hal_type_t type)
    {
        int rc = hal_signal_new(name.c_str(), type);
        if (rc == 0)
            sigs_.push_back(name);
        return rc;
    }

    int comp_ = 0;
    UlPins* p_ = nullptr;
    std::vector<std::string> sigs_;
};

}  // namespace hal_test
