// SPDX-License-Identifier: GPL-2.0-or-later
// The "count=N | names=..." convention (kernel/components/instance_names.h) and
// the depth=/cfg= checks of sampler/streamer (kernel/components/fifo_module.h).
#include <gtest/gtest.h>

#include <string>

#include "instance_names.h"
#include "fifo_module.h"

namespace {

std::string last_message;

extern "C" void capture(msg_level_t, const char* msg) { last_message = msg; }

class Messages : public ::testing::Test {
protected:
    void SetUp() override
    {
        last_message.clear();
        saved_ = rtapi_get_msg_handler();
        rtapi_set_msg_handler(capture);
    }
    void TearDown() override { rtapi_set_msg_handler(saved_); }

private:
    rtapi_msg_handler_t saved_ = nullptr;
};

using InstanceNames = Messages;
using FifoParams = Messages;

TEST_F(InstanceNames, DefaultIsOneInstance)
{
    char* names[4] = {};
    EXPECT_EQ(instance_count("and2", "count", -1, names, 4, 64), 1);
    EXPECT_EQ(last_message, "");
}

TEST_F(InstanceNames, CountGivesThatMany)
{
    char* names[4] = {};
    EXPECT_EQ(instance_count("and2", "count", 5, names, 4, 64), 5);
}

TEST_F(InstanceNames, CountOutOfRangeIsRefused)
{
    char* names[4] = {};
    EXPECT_EQ(instance_count("siggen", "num_chan", 17, names, 4, 16), -EINVAL);
    EXPECT_EQ(last_message, "siggen: num_chan=17 is out of range, must be 1..16\n");
    EXPECT_EQ(instance_count("and2", "count", 65, names, 4, 64), -EINVAL);
}

TEST_F(InstanceNames, CountZeroAndEmptyNamesMeanTheDefault)
{
    char* none[4] = {};
    EXPECT_EQ(instance_count("and2", "count", 0, none, 4, 64), 1);
    char empty[] = "";
    char* blank[4] = {empty};
    EXPECT_EQ(instance_count("and2", "count", -1, blank, 4, 64), 1);
    EXPECT_EQ(instance_count("and2", "count", 3, blank, 4, 64), 3);
}

TEST_F(InstanceNames, NamesGiveOneInstanceEach)
{
    char a[] = "left", b[] = "right";
    char* names[4] = {a, b};
    EXPECT_EQ(instance_count("or2", "count", -1, names, 4, 64), 2);
}

TEST_F(InstanceNames, CountAndNamesTogetherAreRefused)
{
    char a[] = "x";
    char* names[4] = {a};
    EXPECT_EQ(instance_count("and2", "count", 1, names, 4, 64), -EINVAL);
    EXPECT_EQ(last_message,
              "and2: count= and names= are mutually exclusive; give only one of them\n");
}

TEST_F(InstanceNames, DuplicateNameIsRefused)
{
    char a[] = "gate", b[] = "other", c[] = "gate";
    char* names[4] = {a, b, c};
    EXPECT_EQ(instance_count("xor2", "count", -1, names, 4, 64), -EINVAL);
    EXPECT_EQ(last_message, "xor2: names= gives 'gate' twice\n");
}

TEST_F(InstanceNames, PrefixOfANameIsNotADuplicate)
{
    char a[] = "gate", b[] = "gate2";
    char* names[4] = {a, b};
    EXPECT_EQ(instance_count("xor2", "count", -1, names, 4, 64), 2);
}

TEST_F(InstanceNames, EmptyEntryIsRefused)
{
    char a[] = "a", b[] = "";
    char* names[4] = {a, b};
    EXPECT_EQ(instance_count("not", "count", -1, names, 4, 64), -EINVAL);
    EXPECT_EQ(last_message, "not: names= entry 2 is empty\n");
}

TEST_F(InstanceNames, OverlongNameIsRefused)
{
    std::string longname(HAL_NAME_LEN + 1, 'n');
    char* names[4] = {longname.data()};
    EXPECT_EQ(instance_count("not", "count", -1, names, 4, 64), -EINVAL);
    EXPECT_NE(last_message.find("longer than " + std::to_string(HAL_NAME_LEN) + " characters"), std::string::npos);
}

TEST_F(InstanceNames, MoreNamesThanTheMaximumAreRefused)
{
    char a[] = "a", b[] = "b", c[] = "c";
    char* names[4] = {a, b, c};
    EXPECT_EQ(instance_count("siggen", "num_chan", -1, names, 4, 2), -EINVAL);
    EXPECT_EQ(last_message, "siggen: names= gives 3 names, at most 2 are allowed\n");
}

TEST_F(InstanceNames, PrefixIsCompDotIndexWithCount)
{
    char* names[4] = {};
    char buf[HAL_NAME_LEN + 1];
    instance_prefix(buf, sizeof(buf), "and2", names, 3);
    EXPECT_STREQ(buf, "and2.3");
}

TEST_F(InstanceNames, PrefixIsTheNameWithNames)
{
    char a[] = "first", b[] = "second";
    char* names[4] = {a, b};
    char buf[HAL_NAME_LEN + 1];
    instance_prefix(buf, sizeof(buf), "and2", names, 1);
    EXPECT_STREQ(buf, "second");
}

TEST_F(FifoParams, OneDepthPerCfgString)
{
    char a[] = "ffb", b[] = "u";
    char* cfg[HAL_FIFO_MAX_FIFOS] = {a, b};
    int depth[HAL_FIFO_MAX_FIFOS] = {100, 5};
    EXPECT_EQ(fifo_module_count("sampler", cfg, depth), 2);
}

TEST_F(FifoParams, MissingCfgIsRefused)
{
    char* cfg[HAL_FIFO_MAX_FIFOS] = {};
    int depth[HAL_FIFO_MAX_FIFOS] = {100};
    EXPECT_EQ(fifo_module_count("sampler", cfg, depth), -EINVAL);
    EXPECT_EQ(last_message, "sampler: cfg= is required, e.g. loadrt sampler depth=100 cfg=ffb\n");
}

TEST_F(FifoParams, BadCharacterIsNamed)
{
    char a[] = "fbx";
    char* cfg[HAL_FIFO_MAX_FIFOS] = {a};
    int depth[HAL_FIFO_MAX_FIFOS] = {10};
    EXPECT_EQ(fifo_module_count("streamer", cfg, depth), -EINVAL);
    EXPECT_EQ(last_message, "streamer: cfg= string 1 'fbx': bad character 'x', use f, b, s, u, l (s64) or k (u64)\n");
}

TEST_F(FifoParams, TooManyPinsAreRefused)
{
    char a[] = "bbbbbbbbbbbbbbbbbbbbb";  // 21
    char* cfg[HAL_FIFO_MAX_FIFOS] = {a};
    int depth[HAL_FIFO_MAX_FIFOS] = {10};
    EXPECT_EQ(fifo_module_count("sampler", cfg, depth), -EINVAL);
    EXPECT_NE(last_message.find("more than 20 pins"), std::string::npos);
}

TEST_F(FifoParams, MissingDepthIsRefused)
{
    char a[] = "f", b[] = "b";
    char* cfg[HAL_FIFO_MAX_FIFOS] = {a, b};
    int depth[HAL_FIFO_MAX_FIFOS] = {10};
    EXPECT_EQ(fifo_module_count("sampler", cfg, depth), -EINVAL);
    EXPECT_EQ(last_message,
              "sampler: depth= entry 2 is 0; FIFO 1 (cfg=b) needs a depth of 1..1000000\n");
}

TEST_F(FifoParams, ExtraDepthIsRefused)
{
    char a[] = "f";
    char* cfg[HAL_FIFO_MAX_FIFOS] = {a};
    int depth[HAL_FIFO_MAX_FIFOS] = {10, 20};
    EXPECT_EQ(fifo_module_count("sampler", cfg, depth), -EINVAL);
    EXPECT_NE(last_message.find("give one depth per cfg string"), std::string::npos);
}

}  // namespace
