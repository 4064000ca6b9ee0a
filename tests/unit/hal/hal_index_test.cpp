// SPDX-License-Identifier: GPL-2.0-or-later
// hal_index_test.cpp - the name index and kind lists (hal_index.c) on a private
// heap buffer: lookups by kind and name, name rules, creation order, counts, scale.
#include <gtest/gtest.h>
#include <gmock/gmock.h>

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "hal_test_internal.h"
#include "msg_capture.hpp"

extern "C" int hal_format_name(char* buf, const char* what, const char* fmt, va_list ap);

namespace {

using ::testing::HasSubstr;

constexpr rtapi_u32 kSegSize = 16u << 20;   // room for 50k named records

// hal_object_new() and hal_find() work on the global segment: aim it at our buffer.
class HalIndex : public ::testing::Test {
protected:
    void SetUp() override { make_segment(kSegSize); }
    void TearDown() override
    {
        hal_shmem_base = nullptr;
        hal_seg = nullptr;
        std::free(buf_);
    }
    void make_segment(rtapi_u32 size)
    {
        std::free(buf_);
        buf_ = static_cast<char*>(std::aligned_alloc(4096, (size + 4095) & ~4095u));
        ASSERT_NE(buf_, nullptr);
        std::memset(buf_, 0, size);
        seg_ = reinterpret_cast<struct hal_seg_hdr*>(buf_);
        hal_segment_init(seg_, size);
        hal_shmem_base = buf_;
        hal_seg = seg_;
    }
    struct hal_obj_hdr* make(enum hal_kind kind, const std::string& name, int* err_out = nullptr)
    {
        int err = 12345;
        auto* o = static_cast<struct hal_obj_hdr*>(
            hal_object_new(kind, sizeof(struct hal_pin_rec), name.c_str(), 0, &err));
        if (err_out)
            *err_out = err;
        return o;
    }
    struct hal_obj_hdr* find(enum hal_kind kind, const std::string& name)
    {
        return hal_index_find(seg_, kind, name.c_str());
    }
    std::vector<std::string> names(enum hal_kind kind) const
    {
        std::vector<std::string> out;
        for (rtapi_u32 o = seg_->list_head[kind]; o;) {
            auto* h = reinterpret_cast<const struct hal_obj_hdr*>(buf_ + o);
            out.emplace_back(h->name);
            o = h->next_off;
        }
        return out;
    }
    std::vector<std::string> names_backwards(enum hal_kind kind) const
    {
        std::vector<std::string> out;
        for (rtapi_u32 o = seg_->list_tail[kind]; o;) {
            auto* h = reinterpret_cast<const struct hal_obj_hdr*>(buf_ + o);
            out.emplace_back(h->name);
            o = h->prev_off;
        }
        return out;
    }

    char* buf_ = nullptr;
    struct hal_seg_hdr* seg_ = nullptr;
};

TEST_F(HalIndex, FindsACreatedObjectByKindAndName)
{
    int err;
    auto* o = make(HAL_KIND_PIN, "pid.0.command", &err);
    ASSERT_NE(o, nullptr);
    EXPECT_EQ(err, 0);
    EXPECT_EQ(find(HAL_KIND_PIN, "pid.0.command"), o);
    EXPECT_STREQ(o->name, "pid.0.command");
    EXPECT_EQ(o->kind, HAL_KIND_PIN);
}

TEST_F(HalIndex, DoesNotFindAnUnknownName)
{
    make(HAL_KIND_PIN, "a.b");
    EXPECT_EQ(find(HAL_KIND_PIN, "a.c"), nullptr);
    EXPECT_EQ(find(HAL_KIND_PIN, "a.b.c"), nullptr);
    EXPECT_EQ(find(HAL_KIND_PIN, "a."), nullptr);
}

TEST_F(HalIndex, KeepsTheSameNameInDifferentKindsApart)
{
    auto* pin = make(HAL_KIND_PIN, "x.out");
    auto* sig = make(HAL_KIND_SIG, "x.out");
    ASSERT_NE(pin, nullptr);
    ASSERT_NE(sig, nullptr);
    EXPECT_NE(pin, sig);
    EXPECT_EQ(find(HAL_KIND_PIN, "x.out"), pin);
    EXPECT_EQ(find(HAL_KIND_SIG, "x.out"), sig);
    EXPECT_EQ(find(HAL_KIND_PARAM, "x.out"), nullptr);
    hal_object_delete(pin);
    EXPECT_EQ(find(HAL_KIND_PIN, "x.out"), nullptr);
    EXPECT_EQ(find(HAL_KIND_SIG, "x.out"), sig);
}

TEST_F(HalIndex, HashDependsOnTheKind)
{
    EXPECT_NE(hal_name_hash(HAL_KIND_PIN, "abc"), hal_name_hash(HAL_KIND_SIG, "abc"));
    EXPECT_EQ(hal_name_hash(HAL_KIND_PIN, "abc"), hal_name_hash(HAL_KIND_PIN, "abc"));
}

TEST_F(HalIndex, RefusesADuplicateNameOfTheSameKindWithEexist)
{
    hal_test::MsgCapture msgs;
    auto* first = make(HAL_KIND_SIG, "dup");
    int err;
    EXPECT_EQ(make(HAL_KIND_SIG, "dup", &err), nullptr);
    EXPECT_EQ(err, -EEXIST);
    EXPECT_THAT(msgs.text(), HasSubstr("signal 'dup' already exists"));
    EXPECT_EQ(find(HAL_KIND_SIG, "dup"), first);
    EXPECT_EQ(seg_->count[HAL_KIND_SIG], 1u);
}

TEST_F(HalIndex, AcceptsANameOfHalNameLenCharacters)
{
    std::string name(HAL_NAME_LEN, 'n');
    int err;
    ASSERT_NE(make(HAL_KIND_PARAM, name, &err), nullptr);
    EXPECT_EQ(err, 0);
    EXPECT_NE(find(HAL_KIND_PARAM, name), nullptr);
}

TEST_F(HalIndex, RefusesALongerNameNamingTheLimit)
{
    hal_test::MsgCapture msgs;
    std::string name(HAL_NAME_LEN + 1, 'n');
    int err;
    EXPECT_EQ(make(HAL_KIND_PARAM, name, &err), nullptr);
    EXPECT_EQ(err, -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("longer than " + std::to_string(HAL_NAME_LEN) + " characters"));
    EXPECT_EQ(seg_->count[HAL_KIND_PARAM], 0u);
    EXPECT_EQ(seg_->bytes_used, 0u);
}

TEST_F(HalIndex, RefusesAnEmptyName)
{
    hal_test::MsgCapture msgs;
    int err;
    EXPECT_EQ(make(HAL_KIND_PIN, "", &err), nullptr);
    EXPECT_EQ(err, -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("pin name is empty"));
}

TEST_F(HalIndex, RefusesANameWithWhitespaceOrControlCharacters)
{
    struct Case {
        const char* name;
        const char* message;
    };
    for (const Case& c : {Case{"a b", "signal name contains whitespace (at position 2)"},
                          Case{"a\tb", "signal name contains whitespace (at position 2)"},
                          Case{"a\nb", "signal name contains control character 0x0a (at position 2)"},
                          Case{"a\x7f", "signal name contains control character 0x7f (at position 2)"},
                          Case{"\x1b[2Jx", "signal name contains control character 0x1b (at position 1)"}}) {
        hal_test::MsgCapture msgs;
        int err;
        EXPECT_EQ(make(HAL_KIND_SIG, c.name, &err), nullptr) << c.name;
        EXPECT_EQ(err, -EINVAL);
        EXPECT_THAT(msgs.text(), HasSubstr(c.message));
        EXPECT_EQ(msgs.text().find('\x1b'), std::string::npos);  // never echoed raw
    }
    EXPECT_EQ(seg_->count[HAL_KIND_SIG], 0u);
}

// Issue 19, item 9: a non-ASCII name was said to hold whitespace or a control character.
TEST_F(HalIndex, RefusesANonAsciiNameSayingSo)
{
    hal_test::MsgCapture msgs;
    int err;
    EXPECT_EQ(make(HAL_KIND_PIN, "caf\xc3\xa9", &err), nullptr);
    EXPECT_EQ(err, -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("pin name contains a non-ASCII byte 0xc3 (at position 4): "
                                       "HAL names are ASCII"));
}

TEST_F(HalIndex, ListsObjectsOfAKindInCreationOrder)
{
    for (const char* n : {"c", "a", "b"})
        make(HAL_KIND_FUNCT, n);
    make(HAL_KIND_PIN, "other");
    EXPECT_EQ(names(HAL_KIND_FUNCT), (std::vector<std::string>{"c", "a", "b"}));
    EXPECT_EQ(names_backwards(HAL_KIND_FUNCT), (std::vector<std::string>{"b", "a", "c"}));
    EXPECT_EQ(names(HAL_KIND_PIN), (std::vector<std::string>{"other"}));
}

TEST_F(HalIndex, RemovingTheMiddleHeadAndTailKeepsTheListLinked)
{
    auto* a = make(HAL_KIND_THREAD, "a");
    auto* b = make(HAL_KIND_THREAD, "b");
    auto* c = make(HAL_KIND_THREAD, "c");
    auto* d = make(HAL_KIND_THREAD, "d");
    hal_object_delete(b);
    EXPECT_EQ(names(HAL_KIND_THREAD), (std::vector<std::string>{"a", "c", "d"}));
    hal_object_delete(a);
    EXPECT_EQ(names(HAL_KIND_THREAD), (std::vector<std::string>{"c", "d"}));
    hal_object_delete(d);
    EXPECT_EQ(names(HAL_KIND_THREAD), (std::vector<std::string>{"c"}));
    EXPECT_EQ(names_backwards(HAL_KIND_THREAD), (std::vector<std::string>{"c"}));
    make(HAL_KIND_THREAD, "e");
    EXPECT_EQ(names(HAL_KIND_THREAD), (std::vector<std::string>{"c", "e"}));
    hal_object_delete(c);
    hal_object_delete(find(HAL_KIND_THREAD, "e"));
    EXPECT_EQ(seg_->list_head[HAL_KIND_THREAD], 0u);
    EXPECT_EQ(seg_->list_tail[HAL_KIND_THREAD], 0u);
}

TEST_F(HalIndex, CountsFollowCreationAndDeletionPerKind)
{
    auto* p = make(HAL_KIND_PIN, "p1");
    make(HAL_KIND_PIN, "p2");
    make(HAL_KIND_COMP, "c1");
    EXPECT_EQ(seg_->count[HAL_KIND_PIN], 2u);
    EXPECT_EQ(seg_->count[HAL_KIND_COMP], 1u);
    hal_object_delete(p);
    EXPECT_EQ(seg_->count[HAL_KIND_PIN], 1u);
    EXPECT_EQ(seg_->count[HAL_KIND_COMP], 1u);
}

TEST_F(HalIndex, DeletingFreesTheRecordForReuse)
{
    auto* p = make(HAL_KIND_PIN, "p1");
    rtapi_u32 used = seg_->bytes_used;
    hal_object_delete(p);
    EXPECT_LT(seg_->bytes_used, used);
    EXPECT_EQ(make(HAL_KIND_PIN, "p2"), p);
}

TEST_F(HalIndex, NamesSharingABucketStayFindableWhenOneIsRemoved)
{
    // Find three names that land in one bucket.
    std::vector<std::string> same;
    rtapi_u32 want = hal_name_hash(HAL_KIND_PIN, "n0") & (HAL_HASH_BUCKETS - 1);
    same.push_back("n0");
    for (int i = 1; same.size() < 3 && i < 50000000; i++) {
        std::string n = "n" + std::to_string(i);
        if ((hal_name_hash(HAL_KIND_PIN, n.c_str()) & (HAL_HASH_BUCKETS - 1)) == want)
            same.push_back(n);
    }
    ASSERT_EQ(same.size(), 3u);
    for (const auto& n : same)
        make(HAL_KIND_PIN, n);
    hal_object_delete(find(HAL_KIND_PIN, same[1]));   // middle of the chain
    EXPECT_NE(find(HAL_KIND_PIN, same[0]), nullptr);
    EXPECT_EQ(find(HAL_KIND_PIN, same[1]), nullptr);
    EXPECT_NE(find(HAL_KIND_PIN, same[2]), nullptr);
    hal_object_delete(find(HAL_KIND_PIN, same[2]));   // head of the chain (inserted last)
    EXPECT_NE(find(HAL_KIND_PIN, same[0]), nullptr);
    EXPECT_EQ(find(HAL_KIND_PIN, same[2]), nullptr);
}

TEST_F(HalIndex, FiftyThousandNamesStayFindable)
{
    constexpr int kCount = 50000;
    char name[HAL_NAME_LEN + 1];
    for (int i = 0; i < kCount; i++) {
        std::snprintf(name, sizeof(name), "comp.%d.pin-%d", i / 8, i % 8);
        ASSERT_NE(make(HAL_KIND_PIN, name), nullptr) << name;
    }
    EXPECT_EQ(seg_->count[HAL_KIND_PIN], static_cast<rtapi_u32>(kCount));
    for (int i = 0; i < kCount; i++) {
        std::snprintf(name, sizeof(name), "comp.%d.pin-%d", i / 8, i % 8);
        auto* o = find(HAL_KIND_PIN, name);
        ASSERT_NE(o, nullptr) << name;
        ASSERT_STREQ(o->name, name);
    }
    EXPECT_EQ(find(HAL_KIND_PIN, "comp.6250.pin-0"), nullptr);
    EXPECT_EQ(find(HAL_KIND_SIG, "comp.0.pin-0"), nullptr);
    for (int i = 0; i < kCount; i += 2) {
        std::snprintf(name, sizeof(name), "comp.%d.pin-%d", i / 8, i % 8);
        hal_object_delete(find(HAL_KIND_PIN, name));
    }
    for (int i = 0; i < kCount; i++) {
        std::snprintf(name, sizeof(name), "comp.%d.pin-%d", i / 8, i % 8);
        ASSERT_EQ(find(HAL_KIND_PIN, name) != nullptr, i % 2 == 1) << name;
    }
    EXPECT_EQ(seg_->count[HAL_KIND_PIN], static_cast<rtapi_u32>(kCount / 2));
}

TEST_F(HalIndex, ReportsEnomemWhenTheSegmentIsFull)
{
    // the record heap ends where the value area starts: room for exactly two pins
    seg_->val_start = seg_->heap_start + 2 * (sizeof(struct hal_pin_rec) + sizeof(struct hal_block_hdr));
    hal_test::MsgCapture msgs;
    EXPECT_NE(make(HAL_KIND_PIN, "p1"), nullptr);
    EXPECT_NE(make(HAL_KIND_PIN, "p2"), nullptr);
    int err;
    EXPECT_EQ(make(HAL_KIND_PIN, "p3", &err), nullptr);
    EXPECT_EQ(err, -ENOMEM);
    EXPECT_THAT(msgs.text(), HasSubstr("cannot create pin 'p3'"));
    EXPECT_EQ(find(HAL_KIND_PIN, "p3"), nullptr);
    EXPECT_EQ(seg_->count[HAL_KIND_PIN], 2u);
}

int format(char* buf, const char* fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int rc = hal_format_name(buf, "pin", fmt, ap);
    va_end(ap);
    return rc;
}

TEST_F(HalIndex, FormatNameFillsTheBuffer)
{
    char buf[HAL_NAME_LEN + 1];
    EXPECT_EQ(format(buf, "pid.%d.%s", 3, "Pgain"), 0);
    EXPECT_STREQ(buf, "pid.3.Pgain");
}

TEST_F(HalIndex, FormatNameRefusesMoreThanHalNameLenCharacters)
{
    char buf[HAL_NAME_LEN + 1];
    std::string s47(HAL_NAME_LEN, 'x');
    EXPECT_EQ(format(buf, "%s", s47.c_str()), 0);
    hal_test::MsgCapture msgs;
    EXPECT_EQ(format(buf, "%s.", s47.c_str()), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("pin name"));
    EXPECT_THAT(msgs.text(), HasSubstr("longer than " + std::to_string(HAL_NAME_LEN) + " characters"));
}

}  // namespace
