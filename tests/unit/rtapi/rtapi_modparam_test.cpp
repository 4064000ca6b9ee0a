// SPDX-License-Identifier: GPL-2.0-or-later
// rtapi_modparam_test - module parameters: registration through the RTAPI_MP_*
// macros, collection by the host, and rtapi_mp_set for every type and every error.
#include <climits>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_modparam_uspace.h"

// What a component declares (these register at program start, like during dlopen).
static int count = 1;
RTAPI_MP_INT(count, "number of channels")
static long big = 0;
RTAPI_MP_LONG(big, "a long")
static char* names = nullptr;
RTAPI_MP_STRING(names, "instance names")
static int step_type[4] = {-1, -1, -1, -1};
RTAPI_MP_ARRAY_INT(step_type, 4, "step types")
static long offsets[3] = {7, 8, 9};
RTAPI_MP_ARRAY_LONG(offsets, 3, "offsets")
static char* ctrl_type[3] = {nullptr, nullptr, nullptr};
RTAPI_MP_ARRAY_STRING(ctrl_type, 3, "p or v")

int rtapi_app_main(void) { return 0; }
void rtapi_app_exit(void) {}

namespace {

const rtapi_mp_desc* find(const char* name)
{
    static const std::vector<const rtapi_mp_desc*> all = [] {
        const rtapi_mp_desc** list = nullptr;
        int n = rtapi_mp_collect_end(&list);  // everything registered before main()
        return std::vector<const rtapi_mp_desc*>(list, list + n);  // copy: valid until begin
    }();
    for (const rtapi_mp_desc* d : all)
        if (std::strcmp(d->name, name) == 0)
            return d;
    return nullptr;
}

std::string set(const char* name, const char* value, int* ret = nullptr)
{
    char err[128] = "";
    const rtapi_mp_desc* d = find(name);
    if (!d)
        return "no such parameter";
    int r = rtapi_mp_set(d, value, err, sizeof err);
    if (ret)
        *ret = r;
    return r == 0 ? std::string("ok") : std::string(err);
}

TEST(RtapiModparam, ConstructorsRegisterEveryParameter)
{
    for (const char* n : {"count", "big", "names", "step_type", "offsets", "ctrl_type"})
        EXPECT_NE(find(n), nullptr) << n;
    EXPECT_EQ(find("step_type")->num, 4);
    EXPECT_EQ(find("step_type")->type, RTAPI_MP_TYPE_INT);
    EXPECT_STREQ(find("count")->description, "number of channels");
}

TEST(RtapiModparam, CollectBeginForgetsEarlierModules)
{
    find("count");  // make sure the static list was taken before we reset
    rtapi_mp_collect_begin();
    static const rtapi_mp_desc d = {"late", RTAPI_MP_TYPE_INT, &count, 0, ""};
    rtapi_mp_register(&d);
    const rtapi_mp_desc** all;
    ASSERT_EQ(rtapi_mp_collect_end(&all), 1);
    EXPECT_EQ(all[0], &d);
    rtapi_mp_collect_begin();
    EXPECT_EQ(rtapi_mp_collect_end(&all), 0);
}

TEST(RtapiModparam, IntegersInCNotation)
{
    EXPECT_EQ(set("count", "5"), "ok");
    EXPECT_EQ(count, 5);
    EXPECT_EQ(set("count", "0x1f"), "ok");
    EXPECT_EQ(count, 31);
    EXPECT_EQ(set("count", "017"), "ok");
    EXPECT_EQ(count, 15);
    EXPECT_EQ(set("count", "-2147483648"), "ok");
    EXPECT_EQ(count, INT_MIN);
    EXPECT_EQ(set("big", "-9223372036854775808"), "ok");
    EXPECT_EQ(big, LONG_MIN);
}

TEST(RtapiModparam, IntegerErrorsNameTheParameter)
{
    int r = 0;
    count = 3;
    EXPECT_EQ(set("count", "9x", &r), "count: '9x' is not an integer");
    EXPECT_EQ(r, -EINVAL);
    EXPECT_EQ(set("count", ""), "count: '' is not an integer");
    EXPECT_EQ(set("count", " 4"), "count: ' 4' is not an integer");
    EXPECT_EQ(set("count", "08"), "count: '08' is not an integer");
    EXPECT_EQ(set("count", "2147483648"), "count: 2147483648 is out of range for an int (-2147483648..2147483647)");
    EXPECT_EQ(set("big", "9223372036854775808"),
              "big: 9223372036854775808 is out of range for a long (-9223372036854775808..9223372036854775807)");
    EXPECT_EQ(count, 3);
    char err[64];
    EXPECT_EQ(rtapi_mp_set(find("count"), nullptr, err, sizeof err), -EINVAL);
    EXPECT_STREQ(err, "count: no value given");
}

TEST(RtapiModparam, StringsAreCopied)
{
    std::string v = "x,y,z";
    EXPECT_EQ(set("names", v.c_str()), "ok");
    v[0] = 'Q';
    EXPECT_STREQ(names, "x,y,z");  // a scalar string keeps its commas
    EXPECT_EQ(set("names", ""), "ok");
    EXPECT_STREQ(names, "");
}

TEST(RtapiModparam, ArraysTakeCommaSeparatedLists)
{
    EXPECT_EQ(set("step_type", "0,0,2"), "ok");
    EXPECT_EQ(step_type[0], 0);
    EXPECT_EQ(step_type[1], 0);
    EXPECT_EQ(step_type[2], 2);
    EXPECT_EQ(step_type[3], -1);  // not given: unchanged
    EXPECT_EQ(set("offsets", "-1,0x10"), "ok");
    EXPECT_EQ(offsets[0], -1);
    EXPECT_EQ(offsets[1], 16);
    EXPECT_EQ(offsets[2], 9);
    EXPECT_EQ(set("ctrl_type", "p,p,v"), "ok");
    EXPECT_STREQ(ctrl_type[0], "p");
    EXPECT_STREQ(ctrl_type[2], "v");
    EXPECT_EQ(set("ctrl_type", "v"), "ok");
    EXPECT_STREQ(ctrl_type[0], "v");
    EXPECT_STREQ(ctrl_type[1], "p");
}

TEST(RtapiModparam, ArrayErrorsChangeNothing)
{
    ASSERT_EQ(set("step_type", "1,2,3,4"), "ok");
    EXPECT_EQ(set("step_type", "1,2,3,4,5"), "step_type: 5 values given, at most 4 allowed");
    EXPECT_EQ(set("step_type", "5,9x"), "step_type: '9x' is not an integer");
    EXPECT_EQ(set("step_type", "5,,6"), "step_type: value 2 of 3 is empty");
    EXPECT_EQ(set("step_type", "5,"), "step_type: value 2 of 2 is empty");
    EXPECT_EQ(set("step_type", ""), "step_type: value 1 of 1 is empty");
    EXPECT_EQ(set("ctrl_type", "p,,v"), "ctrl_type: value 2 of 3 is empty");
    EXPECT_EQ(step_type[0], 1);
    EXPECT_EQ(step_type[1], 2);
}

TEST(RtapiModparam, EmptyStringArrayIsOneEmptyString)
{
    // "names=": as the kernel's module_param_array leaves it; components then use
    // their default count (LinuxCNC).
    EXPECT_EQ(set("ctrl_type", ""), "ok");
    EXPECT_STREQ(ctrl_type[0], "");
    EXPECT_EQ(set("ctrl_type", "p,"), "ctrl_type: value 2 of 2 is empty");
}

}  // namespace
