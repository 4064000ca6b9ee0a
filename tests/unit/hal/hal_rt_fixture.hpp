// SPDX-License-Identifier: GPL-2.0-or-later
// hal_rt_fixture.hpp - the test process acts as a realtime host (like rtapi_app):
// an RTAPI_INSTANCE of its own, one anchor component that keeps the segment mapped
// for the whole run, and a fixture component per test that takes everything it made
// away again. Shared by the hal_api_rt_test sources.
#pragma once
#include <gtest/gtest.h>
#include <gmock/gmock.h>

#include <string>
#include <vector>

#include "hal.h"
#include "hal_host.h"
#include "hal_test_internal.h"
#include "msg_capture.hpp"

namespace hal_test {

// The POSIX shm object of this process's HAL segment (/dev/shm/...).
std::string hal_shm_path();
// Remove and re-create the anchor component (for tests of the unmapped state).
void drop_anchor();
void restore_anchor();

template <class Rec>
Rec* find_rec(enum hal_kind kind, const std::string& name)
{
    return reinterpret_cast<Rec*>(hal_index_find(hal_seg, kind, name.c_str()));
}
inline struct hal_pin_rec* pin_rec(const std::string& n) { return find_rec<struct hal_pin_rec>(HAL_KIND_PIN, n); }
inline struct hal_sig_rec* sig_rec(const std::string& n) { return find_rec<struct hal_sig_rec>(HAL_KIND_SIG, n); }
inline struct hal_param_rec* param_rec(const std::string& n) { return find_rec<struct hal_param_rec>(HAL_KIND_PARAM, n); }
inline struct hal_funct_rec* funct_rec(const std::string& n) { return find_rec<struct hal_funct_rec>(HAL_KIND_FUNCT, n); }
inline struct hal_thread_rec* thread_rec(const std::string& n) { return find_rec<struct hal_thread_rec>(HAL_KIND_THREAD, n); }
inline struct hal_comp_rec* comp_rec(const std::string& n) { return find_rec<struct hal_comp_rec>(HAL_KIND_COMP, n); }
inline void* seg_ptr(rtapi_u32 off) { return off ? hal_shmem_base + off : nullptr; }
// What a thread writes each period (struct hal_thread_rt): cycles, run time, tmax.
inline struct hal_thread_rt* thread_rt(const std::string& n)
{
    return static_cast<struct hal_thread_rt*>(seg_ptr(thread_rec(n)->rt_off));
}

// Function names of a thread in execution order, read from the segment.
std::vector<std::string> thread_functs(const std::string& thread);

// Pin storage a component keeps in hal_malloc() memory.
struct PinPtrs {
    hal_bit_t* b[4];
    hal_float_t* f[4];
    hal_s32_t* s[4];
    hal_u32_t* u[4];
};
struct ParamVals {
    hal_bit_t b;
    hal_float_t f;
    hal_s32_t s;
    hal_u32_t u;
};

class HalRt : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    // A signal that TearDown deletes again (signals belong to no component).
    int new_signal(const std::string& name, hal_type_t type);
    // A thread with period_ns that the fixture component owns.
    int new_thread(const std::string& name, unsigned long period_ns, int uses_fp);
    template <class T>
    T* mem()
    {
        return static_cast<T*>(hal_malloc(sizeof(T)));
    }

    int comp_ = 0;
    PinPtrs* pins_ = nullptr;
    std::vector<std::string> sigs_;
};

}  // namespace hal_test
