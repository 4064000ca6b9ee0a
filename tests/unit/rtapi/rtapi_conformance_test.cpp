// SPDX-License-Identifier: GPL-2.0-or-later
// rtapi_conformance_test - the RTAPI conformance suite (tests/kernel/rtapi_conformance.c,
// shared with the kernel flavor's VM test) in the simulated flavor: one test per case.
#include <gtest/gtest.h>

#include <string>

#include "rtapi.h"
#include "rtapi_conformance.h"

namespace {

class Conformance : public ::testing::TestWithParam<int> {};

TEST_P(Conformance, BehavesAsDocumented)
{
    const rtapi_conf_case& c = rtapi_conf_cases[GetParam()];
    char why[160] = "";
    EXPECT_EQ(c.run(why, sizeof(why)), 0) << c.name << ": " << why;
}

INSTANTIATE_TEST_SUITE_P(Rtapi, Conformance, ::testing::Range(0, rtapi_conf_ncases),
                         [](const ::testing::TestParamInfo<int>& info) {
                             std::string n = rtapi_conf_cases[info.param].name;
                             for (char& ch : n)
                                 if (ch == '-')
                                     ch = '_';
                             return n;
                         });

}  // namespace
