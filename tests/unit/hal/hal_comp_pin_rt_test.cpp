// SPDX-License-Identifier: GPL-2.0-or-later
// hal_comp_pin_rt_test.cpp - components (hal_init/hal_ready/hal_exit/hal_malloc)
// and pins (hal_pin_new(3hal)) through the public API, realtime flavor.
#include "hal_rt_fixture.hpp"

#include <cstring>

namespace hal_test {
namespace {

using ::testing::HasSubstr;

TEST(HalUninitialised, EveryCallRefusesBeforeHalInit)
{
    drop_anchor();
    ASSERT_EQ(hal_seg, nullptr);
    MsgCapture msgs;
    hal_bit_t* p = nullptr;
    hal_bit_t v = 0;
    EXPECT_EQ(hal_exit(1), -EINVAL);
    EXPECT_EQ(hal_ready(1), -EINVAL);
    EXPECT_EQ(hal_set_constructor(1, nullptr), -EINVAL);
    EXPECT_EQ(hal_malloc(8), nullptr);
    EXPECT_EQ(hal_pin_bit_new("x.p", HAL_IN, &p, 1), -EINVAL);
    EXPECT_EQ(hal_param_bit_new("x.q", HAL_RW, &v, 1), -EINVAL);
    EXPECT_EQ(hal_param_bit_set("x.q", 1), -EINVAL);
    EXPECT_EQ(hal_signal_new("s", HAL_BIT), -EINVAL);
    EXPECT_EQ(hal_signal_delete("s"), -EINVAL);
    EXPECT_EQ(hal_link("x.p", "s"), -EINVAL);
    EXPECT_EQ(hal_unlink("x.p"), -EINVAL);
    EXPECT_EQ(hal_export_funct("x.f", [](void*, long) {}, nullptr, 0, 0, 1), -EINVAL);
    EXPECT_EQ(hal_create_thread("t", 1000000, 0), -EINVAL);
    EXPECT_EQ(hal_thread_delete("t"), -EINVAL);
    EXPECT_EQ(hal_add_funct_to_thread("x.f", "t", 1), -EINVAL);
    EXPECT_EQ(hal_del_funct_from_thread("x.f", "t"), -EINVAL);
    EXPECT_EQ(hal_start_threads(), -EINVAL);
    EXPECT_EQ(hal_stop_threads(), -EINVAL);
    EXPECT_EQ(hal_set_lock(HAL_LOCK_ALL), -EINVAL);
    EXPECT_EQ(hal_get_lock(), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("hal_init"));
    restore_anchor();
}

TEST_F(HalRt, InitGivesAPositiveIdAndExitRemovesTheComponent)
{
    int id = hal_init("rt.other");
    ASSERT_GT(id, 0);
    EXPECT_NE(id, comp_);
    auto* c = comp_rec("rt.other");
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->comp_id, id);
    EXPECT_EQ(hal_exit(id), 0);
    EXPECT_EQ(comp_rec("rt.other"), nullptr);
}

TEST_F(HalRt, ARealtimeComponentIsMarkedRealtimeWithoutPid)
{
    auto* c = comp_rec("rt");
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->is_realtime, 1);
    EXPECT_EQ(c->pid, 0);
    EXPECT_EQ(c->is_ready, 0);
}

TEST_F(HalRt, InitAcceptsANameOfHalNameLenCharacters)
{
    std::string name(HAL_NAME_LEN, 'c');
    int id = hal_init(name.c_str());
    ASSERT_GT(id, 0);
    EXPECT_EQ(hal_exit(id), 0);
}

TEST_F(HalRt, InitRefusesALongerNameWithEinval)
{
    MsgCapture msgs;
    std::string name(HAL_NAME_LEN + 1, 'c');
    EXPECT_EQ(hal_init(name.c_str()), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("longer than " + std::to_string(HAL_NAME_LEN) + " characters"));
    EXPECT_EQ(comp_rec(name), nullptr);
}

TEST_F(HalRt, InitRefusesADuplicateNameWithEexist)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_init("rt"), -EEXIST);
    EXPECT_THAT(msgs.text(), HasSubstr("component 'rt' already exists"));
}

TEST_F(HalRt, InitWithoutANameMakesUpOne)
{
    int id = hal_init(nullptr);
    ASSERT_GT(id, 0);
    struct hal_comp_rec* found = nullptr;
    for (rtapi_u32 o = hal_seg->list_head[HAL_KIND_COMP]; o; o = static_cast<hal_obj_hdr*>(seg_ptr(o))->next_off)
        if (static_cast<hal_comp_rec*>(seg_ptr(o))->comp_id == id)
            found = static_cast<hal_comp_rec*>(seg_ptr(o));
    ASSERT_NE(found, nullptr);
    EXPECT_EQ(std::strncmp(found->hdr.name, "comp", 4), 0);
    EXPECT_EQ(hal_exit(id), 0);
}

TEST_F(HalRt, ReadyMarksTheComponentReady)
{
    EXPECT_EQ(hal_ready(comp_), 0);
    EXPECT_EQ(comp_rec("rt")->is_ready, 1);
}

TEST_F(HalRt, ReadyExitAndSetConstructorRefuseAnUnknownId)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_ready(9999), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("component id 9999 does not exist"));
    EXPECT_EQ(hal_exit(9999), -EINVAL);
    EXPECT_EQ(hal_set_constructor(9999, nullptr), -EINVAL);
}

int dummy_constructor(const char*, const char*) { return 0; }

TEST_F(HalRt, SetConstructorRecordsTheFunction)
{
    EXPECT_EQ(hal_set_constructor(comp_, dummy_constructor), 0);
    EXPECT_EQ(comp_rec("rt")->constructor, reinterpret_cast<rtapi_u64>(&dummy_constructor));
}

TEST_F(HalRt, MallocReturnsZeroedAlignedSegmentMemoryOwnedByTheComponent)
{
    auto* p = static_cast<unsigned char*>(hal_malloc(37));
    ASSERT_NE(p, nullptr);
    EXPECT_EQ((p - reinterpret_cast<unsigned char*>(hal_shmem_base)) % 8, 0);
    for (int i = 0; i < 37; i++)
        EXPECT_EQ(p[i], 0);
    auto* blk = reinterpret_cast<struct hal_block_hdr*>(p) - 1;
    EXPECT_EQ(blk->kind, HAL_KIND_MALLOC);
    EXPECT_EQ(blk->owner_off, static_cast<rtapi_u32>(reinterpret_cast<char*>(comp_rec("rt")) - hal_shmem_base));
}

TEST_F(HalRt, MallocRefusesZeroNegativeAndHugeSizes)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_malloc(0), nullptr);
    EXPECT_EQ(hal_malloc(-5), nullptr);
    EXPECT_EQ(hal_malloc(static_cast<long>(HAL_SEGMENT_SIZE_DEFAULT)), nullptr);
    EXPECT_THAT(msgs.text(), HasSubstr("hal_malloc: bad size"));
}

TEST_F(HalRt, MallocReportsAFullSegment)
{
    MsgCapture msgs;
    rtapi_u32 used = hal_seg->bytes_used;
    EXPECT_EQ(hal_malloc(static_cast<long>(HAL_SEGMENT_SIZE_DEFAULT) - 1), nullptr);
    EXPECT_THAT(msgs.text(), HasSubstr("hal_malloc: HAL shared memory is full"));
    EXPECT_EQ(hal_seg->bytes_used, used);
}

TEST_F(HalRt, ExitReturnsEveryByteTheComponentUsed)
{
    ASSERT_EQ(new_signal("rt.reclaim", HAL_FLOAT), 0);
    ASSERT_EQ(new_thread("rt.keep", 1000000, 1), 0);   // owned by the fixture component
    rtapi_u32 used = hal_seg->bytes_used, top = hal_seg->heap_top;

    int id = hal_init("rt.gone");
    ASSERT_GT(id, 0);
    auto* pp = mem<PinPtrs>();
    auto* vals = mem<ParamVals>();
    ASSERT_NE(hal_malloc(1000), nullptr);
    ASSERT_EQ(hal_pin_float_new("rt.gone.in", HAL_IN, &pp->f[0], id), 0);
    ASSERT_EQ(hal_pin_bit_new("rt.gone.out", HAL_OUT, &pp->b[0], id), 0);
    ASSERT_EQ(hal_param_float_new("rt.gone.gain", HAL_RW, &vals->f, id), 0);
    ASSERT_EQ(hal_export_funct("rt.gone.f", [](void*, long) {}, nullptr, 1, 0, id), 0);
    ASSERT_EQ(hal_create_thread("rt.gone.thread", 2000000, 1), 0);   // made while rt.gone loads
    ASSERT_EQ(hal_add_funct_to_thread("rt.gone.f", "rt.keep", 1), 0);
    ASSERT_EQ(hal_link("rt.gone.in", "rt.reclaim"), 0);
    EXPECT_GT(hal_seg->bytes_used, used);

    ASSERT_EQ(hal_exit(id), 0);
    EXPECT_EQ(sig_rec("rt.reclaim")->readers, 0);
    EXPECT_TRUE(thread_functs("rt.keep").empty());
    // threads(9): a thread stands alone once created; deleting it returns the rest.
    EXPECT_NE(thread_rec("rt.gone.thread"), nullptr);
    EXPECT_NE(pin_rec("rt.gone.thread.time"), nullptr);
    ASSERT_EQ(hal_thread_delete("rt.gone.thread"), 0);
    EXPECT_EQ(pin_rec("rt.gone.thread.time"), nullptr);
    EXPECT_EQ(hal_seg->bytes_used, used);
    EXPECT_EQ(hal_seg->heap_top, top);
}

TEST_F(HalRt, CreatesPinsOfEveryTypeAndDirection)
{
    const hal_pin_dir_t dirs[] = {HAL_IN, HAL_OUT, HAL_IO};
    for (int d = 0; d < 3; d++) {
        std::string n = "rt." + std::to_string(d);
        ASSERT_EQ(hal_pin_bit_new((n + ".b").c_str(), dirs[d], &pins_->b[d], comp_), 0);
        ASSERT_EQ(hal_pin_float_new((n + ".f").c_str(), dirs[d], &pins_->f[d], comp_), 0);
        ASSERT_EQ(hal_pin_s32_new((n + ".s").c_str(), dirs[d], &pins_->s[d], comp_), 0);
        ASSERT_EQ(hal_pin_u32_new((n + ".u").c_str(), dirs[d], &pins_->u[d], comp_), 0);
        EXPECT_EQ(pin_rec(n + ".b")->type, HAL_BIT);
        EXPECT_EQ(pin_rec(n + ".f")->type, HAL_FLOAT);
        EXPECT_EQ(pin_rec(n + ".s")->type, HAL_S32);
        EXPECT_EQ(pin_rec(n + ".u")->type, HAL_U32);
        EXPECT_EQ(pin_rec(n + ".u")->dir, dirs[d]);
        EXPECT_NE(pins_->b[d], nullptr);
        EXPECT_NE(pins_->u[d], nullptr);
    }
}

TEST_F(HalRt, GenericPinNewCreatesAPin)
{
    ASSERT_EQ(hal_pin_new("rt.gen", HAL_S32, HAL_IO, (void**)&pins_->s[0], comp_), 0);
    EXPECT_EQ(pin_rec("rt.gen")->type, HAL_S32);
    EXPECT_EQ(pin_rec("rt.gen")->dir, HAL_IO);
}

TEST_F(HalRt, NewfFormatsThePinName)
{
    ASSERT_EQ(hal_pin_float_newf(HAL_IN, &pins_->f[0], comp_, "rt.%d.%s", 3, "command"), 0);
    ASSERT_EQ(hal_pin_bit_newf(HAL_OUT, &pins_->b[0], comp_, "rt.%d.enable", 3), 0);
    ASSERT_EQ(hal_pin_s32_newf(HAL_OUT, &pins_->s[0], comp_, "rt.%s", "count"), 0);
    ASSERT_EQ(hal_pin_u32_newf(HAL_IN, &pins_->u[0], comp_, "rt.%02d", 7), 0);
    EXPECT_NE(pin_rec("rt.3.command"), nullptr);
    EXPECT_NE(pin_rec("rt.3.enable"), nullptr);
    EXPECT_NE(pin_rec("rt.count"), nullptr);
    EXPECT_NE(pin_rec("rt.07"), nullptr);
}

TEST_F(HalRt, NewfRefusesAFormattedNameLongerThanHalNameLen)
{
    MsgCapture msgs;
    std::string tail(HAL_NAME_LEN - 2, 'x');
    EXPECT_EQ(hal_pin_bit_newf(HAL_IN, &pins_->b[0], comp_, "rt.%s", tail.c_str()), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("longer than " + std::to_string(HAL_NAME_LEN) + " characters"));
    EXPECT_EQ(pin_rec("rt." + tail), nullptr);
}

TEST_F(HalRt, PinNewRefusesAnInvalidTypeOrDirection)
{
    MsgCapture msgs;
    void** p = (void**)&pins_->f[0];
    EXPECT_EQ(hal_pin_new("rt.bad", static_cast<hal_type_t>(9), HAL_IN, p, comp_), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("pin 'rt.bad': invalid type 9"));
    EXPECT_EQ(hal_pin_new("rt.bad", HAL_FLOAT, static_cast<hal_pin_dir_t>(HAL_RW), p, comp_), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("pin 'rt.bad': invalid direction"));
    EXPECT_EQ(pin_rec("rt.bad"), nullptr);
}

TEST_F(HalRt, PinNewRefusesADataPointerOutsideHalMemory)
{
    MsgCapture msgs;
    hal_float_t* on_stack = nullptr;
    EXPECT_EQ(hal_pin_float_new("rt.stack", HAL_IN, &on_stack, comp_), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("pin 'rt.stack': its data pointer is not in HAL shared memory"));
    EXPECT_EQ(pin_rec("rt.stack"), nullptr);
    EXPECT_EQ(on_stack, nullptr);
}

TEST_F(HalRt, PinNewRefusesADuplicateName)
{
    ASSERT_EQ(hal_pin_bit_new("rt.dup", HAL_IN, &pins_->b[0], comp_), 0);
    MsgCapture msgs;
    EXPECT_EQ(hal_pin_bit_new("rt.dup", HAL_OUT, &pins_->b[1], comp_), -EEXIST);
    EXPECT_THAT(msgs.text(), HasSubstr("pin 'rt.dup' already exists"));
    EXPECT_EQ(pin_rec("rt.dup")->dir, HAL_IN);
}

TEST_F(HalRt, PinNewRefusesAnUnknownComponent)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_pin_bit_new("rt.orphan", HAL_IN, &pins_->b[0], 9999), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("pin 'rt.orphan': component id 9999 does not exist"));
}

TEST_F(HalRt, AnUnlinkedPinPointsAtItsOwnDummyStorage)
{
    ASSERT_EQ(hal_pin_float_new("rt.a", HAL_OUT, &pins_->f[0], comp_), 0);
    ASSERT_EQ(hal_pin_float_new("rt.b", HAL_OUT, &pins_->f[1], comp_), 0);
    EXPECT_EQ(pins_->f[0], &hal_pin_dummy(pin_rec("rt.a"))->f);
    EXPECT_NE(pins_->f[0], pins_->f[1]);
    *pins_->f[0] = 2.5;
    *pins_->f[1] = -1.0;
    EXPECT_EQ(*pins_->f[0], 2.5);
    EXPECT_EQ(hal_pin_dummy(pin_rec("rt.a"))->f, 2.5);
    EXPECT_EQ(hal_pin_dummy(pin_rec("rt.b"))->f, -1.0);
}

TEST_F(HalRt, ANewPinStartsAtZero)
{
    ASSERT_EQ(hal_pin_s32_new("rt.z", HAL_IN, &pins_->s[0], comp_), 0);
    EXPECT_EQ(*pins_->s[0], 0);
}

TEST_F(HalRt, ExitOfAComponentUnlinksItsPinsFromSignals)
{
    ASSERT_EQ(new_signal("rt.sig", HAL_BIT), 0);
    int id = hal_init("rt.writer");
    ASSERT_GT(id, 0);
    auto* pp = mem<PinPtrs>();
    ASSERT_EQ(hal_pin_bit_new("rt.writer.out", HAL_OUT, &pp->b[0], id), 0);
    ASSERT_EQ(hal_link("rt.writer.out", "rt.sig"), 0);
    *pp->b[0] = true;
    ASSERT_EQ(hal_exit(id), 0);
    EXPECT_EQ(sig_rec("rt.sig")->writers, 0);
    EXPECT_EQ(hal_sig_value(sig_rec("rt.sig"))->b, true);   // the signal keeps its value
    ASSERT_EQ(hal_pin_bit_new("rt.new.out", HAL_OUT, &pins_->b[0], comp_), 0);
    EXPECT_EQ(hal_link("rt.new.out", "rt.sig"), 0);   // the writer slot is free again
}

}  // namespace
}  // namespace hal_test
