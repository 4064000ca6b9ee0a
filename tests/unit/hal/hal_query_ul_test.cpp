// SPDX-License-Identifier: GPL-2.0-or-later
// hal_query_ul_test.cpp - the userspace flavor: hal_attach, userspace components,
// what ULAPI refuses, and the tool API of hal_query.h (queries, finds, checked sets).
#include "hal_ul_fixture.hpp"

#include <sys/wait.h>
#include <unistd.h>

namespace hal_test {
namespace {

using ::testing::HasSubstr;

TEST(HalAttach, AttachIsIdempotent)
{
    int users = hal_local_users;
    EXPECT_EQ(hal_attach(), 0);
    EXPECT_EQ(hal_attach(), 0);
    EXPECT_EQ(hal_local_users, users);
    EXPECT_NE(hal_seg, nullptr);
}

TEST(HalAttach, DetachingTheLastUserUnmapsAndQueriesThenRefuse)
{
    hal_detach();
    ASSERT_EQ(hal_seg, nullptr);
    MsgCapture msgs;
    struct hal_pin_info pin;
    union hal_value v = {};
    unsigned long used, total;
    std::vector<hal_pin_info> pins;
    EXPECT_EQ(hal_query_pins(collect<hal_pin_info>, &pins), -EINVAL);
    EXPECT_EQ(hal_find_pin("x", &pin), -EINVAL);
    EXPECT_EQ(hal_set_pin_value("x", &v), -EINVAL);
    EXPECT_EQ(hal_memory_usage(&used, &total), -EINVAL);
    EXPECT_FALSE(hal_threads_running());
    EXPECT_EQ(hal_base_period(), 0);
    EXPECT_THAT(msgs.text(), HasSubstr("HAL is not attached"));
    ASSERT_EQ(hal_attach(), 0);
}

// halcmd unloadusr removes the component of a process that died without hal_exit().
TEST(HalAttach, RemovingAnotherProcesssComponentKeepsThisProcessAttached)
{
    pid_t child = fork();
    if (child == 0)
        _exit(hal_init("ul.dead") > 0 ? 0 : 1);   // dies without hal_exit()
    int status = -1;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_EQ(status, 0);
    struct hal_comp_info c;
    ASSERT_EQ(hal_find_comp("ul.dead", &c), 0);
    EXPECT_EQ(c.pid, child);
    EXPECT_EQ(hal_exit(c.id), 0);
    EXPECT_NE(hal_seg, nullptr) << "this process only attached; it must stay attached";
    EXPECT_EQ(hal_find_comp("ul.dead", &c), -ENOENT);
}

TEST_F(HalUl, AUserspaceComponentIsNotRealtimeAndRecordsItsPid)
{
    struct hal_comp_info c;
    ASSERT_EQ(hal_find_comp("ul", &c), 0);
    EXPECT_EQ(c.id, comp_);
    EXPECT_FALSE(c.is_realtime);
    EXPECT_EQ(c.pid, getpid());
    EXPECT_FALSE(c.is_ready);
    EXPECT_STREQ(c.module, "");
    EXPECT_STREQ(c.args, "");
    ASSERT_EQ(hal_ready(comp_), 0);
    ASSERT_EQ(hal_find_comp("ul", &c), 0);
    EXPECT_TRUE(c.is_ready);
}

TEST_F(HalUl, ExportFunctIsRefusedInUserspace)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_export_funct("ul.f", [](void*, long) {}, nullptr, 0, 0, comp_), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("function 'ul.f': only realtime components can export functions"));
    struct hal_funct_info f;
    EXPECT_EQ(hal_find_funct("ul.f", &f), -ENOENT);
}

TEST_F(HalUl, CreateThreadIsRefusedInUserspace)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_create_thread("ul.thread", 1000000, 0), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("thread 'ul.thread': only realtime components can create threads"));
    EXPECT_EQ(hal_base_period(), 0);
}

TEST_F(HalUl, ThreadDeleteOfAnUnknownThreadIsEnoent)
{
    EXPECT_EQ(hal_thread_delete("ul.nosuch"), -ENOENT);
}

TEST_F(HalUl, QueryPinsVisitsEveryPinWithItsDetails)
{
    for (int i = 0; i < 4; i++)
        ASSERT_EQ(hal_pin_float_newf(HAL_IN, &p_->f[i], comp_, "ul.f%d", i), 0);
    ASSERT_EQ(hal_pin_bit_new("ul.b", HAL_OUT, &p_->b[0], comp_), 0);
    ASSERT_EQ(hal_pin_u32_new("ul.u", HAL_IO, &p_->u[0], comp_), 0);
    ASSERT_EQ(new_signal("ul.sig", HAL_BIT), 0);
    ASSERT_EQ(hal_link("ul.b", "ul.sig"), 0);
    *p_->f[2] = 0.5;
    *p_->b[0] = true;
    *p_->u[0] = 4000000000u;

    std::vector<hal_pin_info> pins;
    EXPECT_EQ(hal_query_pins(collect<hal_pin_info>, &pins), static_cast<int>(hal_seg->count[HAL_KIND_PIN]));
    EXPECT_EQ(pins.size(), 6u);
    ASSERT_NE(by_name(pins, "ul.f2"), nullptr);
    const auto& f2 = *by_name(pins, "ul.f2");
    EXPECT_STREQ(f2.owner, "ul");
    EXPECT_EQ(f2.owner_id, comp_);
    EXPECT_EQ(f2.type, HAL_FLOAT);
    EXPECT_EQ(f2.dir, HAL_IN);
    EXPECT_EQ(f2.value.f, 0.5);
    EXPECT_STREQ(f2.signal, "");
    const auto* b = by_name(pins, "ul.b");
    ASSERT_NE(b, nullptr);
    EXPECT_TRUE(b->value.b);
    EXPECT_STREQ(b->signal, "ul.sig");
    EXPECT_EQ(by_name(pins, "ul.u")->value.u, 4000000000u);
    EXPECT_EQ(by_name(pins, "ul.u")->dir, HAL_IO);
}

int stop_at_first(const hal_pin_info*, void* ctx)
{
    ++*static_cast<int*>(ctx);
    return 1;
}

TEST_F(HalUl, AQueryStopsWhenTheCallbackReturnsNonzero)
{
    ASSERT_EQ(hal_pin_bit_new("ul.b0", HAL_IN, &p_->b[0], comp_), 0);
    ASSERT_EQ(hal_pin_bit_new("ul.b1", HAL_IN, &p_->b[1], comp_), 0);
    int calls = 0;
    EXPECT_EQ(hal_query_pins(stop_at_first, &calls), 1) << "returns the number visited";
    EXPECT_EQ(calls, 1);
}

TEST_F(HalUl, QueryCompsParamsAndSignalsVisitEverything)
{
    ASSERT_EQ(hal_param_float_new("ul.gain", HAL_RW, &p_->gain, comp_), 0);
    ASSERT_EQ(hal_param_float_new("ul.ro", HAL_RO, &p_->ro, comp_), 0);
    p_->gain = 1.5;
    ASSERT_EQ(hal_pin_s32_new("ul.io", HAL_IO, &p_->s[0], comp_), 0);
    ASSERT_EQ(hal_pin_s32_new("ul.in", HAL_IN, &p_->s[1], comp_), 0);
    ASSERT_EQ(new_signal("ul.s1", HAL_S32), 0);
    ASSERT_EQ(new_signal("ul.s2", HAL_U32), 0);
    ASSERT_EQ(hal_link("ul.io", "ul.s1"), 0);
    ASSERT_EQ(hal_link("ul.in", "ul.s1"), 0);

    std::vector<hal_comp_info> comps;
    std::vector<hal_param_info> params;
    std::vector<hal_sig_info> sigs;
    EXPECT_EQ(hal_query_comps(collect<hal_comp_info>, &comps), 1);
    EXPECT_EQ(hal_query_params(collect<hal_param_info>, &params), 2);
    EXPECT_EQ(hal_query_sigs(collect<hal_sig_info>, &sigs), 2);
    ASSERT_NE(by_name(comps, "ul"), nullptr);
    const auto* gain = by_name(params, "ul.gain");
    ASSERT_NE(gain, nullptr);
    EXPECT_EQ(gain->value.f, 1.5);
    EXPECT_EQ(gain->dir, HAL_RW);
    EXPECT_STREQ(gain->owner, "ul");
    EXPECT_EQ(by_name(params, "ul.ro")->dir, HAL_RO);
    const auto* s1 = by_name(sigs, "ul.s1");
    ASSERT_NE(s1, nullptr);
    EXPECT_EQ(s1->type, HAL_S32);
    EXPECT_EQ(s1->readers, 1);
    EXPECT_EQ(s1->writers, 0);
    EXPECT_EQ(s1->bidirs, 1);
    EXPECT_EQ(by_name(sigs, "ul.s2")->readers, 0);
}

TEST_F(HalUl, QueriesOfFunctionsAndThreadsVisitNothingWithoutRealtimeCode)
{
    std::vector<hal_funct_info> functs;
    std::vector<hal_thread_info> threads;
    EXPECT_EQ(hal_query_functs(collect<hal_funct_info>, &functs), 0);
    EXPECT_EQ(hal_query_threads(collect<hal_thread_info>, &threads), 0);
    EXPECT_EQ(hal_query_thread_functs("nosuch", [](const char*, void*) { return 0; }, nullptr), -ENOENT);
}

TEST_F(HalUl, FindReturnsEnoentForUnknownNamesOfEveryKind)
{
    struct hal_comp_info c;
    struct hal_pin_info p;
    struct hal_param_info pa;
    struct hal_sig_info s;
    struct hal_funct_info f;
    struct hal_thread_info t;
    MsgCapture msgs;
    EXPECT_EQ(hal_find_comp("nosuch", &c), -ENOENT);
    EXPECT_EQ(hal_find_pin("nosuch", &p), -ENOENT);
    EXPECT_EQ(hal_find_param("nosuch", &pa), -ENOENT);
    EXPECT_EQ(hal_find_sig("nosuch", &s), -ENOENT);
    EXPECT_EQ(hal_find_funct("nosuch", &f), -ENOENT);
    EXPECT_EQ(hal_find_thread("nosuch", &t), -ENOENT);
    EXPECT_EQ(msgs.text(), "") << "lookups print nothing";
}

TEST_F(HalUl, FindSigSeesAValueWrittenThroughTheWritersPointer)
{
    ASSERT_EQ(hal_pin_float_new("ul.out", HAL_OUT, &p_->f[0], comp_), 0);
    ASSERT_EQ(new_signal("ul.s", HAL_FLOAT), 0);
    ASSERT_EQ(hal_link("ul.out", "ul.s"), 0);
    *p_->f[0] = -2.75;
    struct hal_sig_info s;
    ASSERT_EQ(hal_find_sig("ul.s", &s), 0);
    EXPECT_EQ(s.value.f, -2.75);
    EXPECT_EQ(s.writers, 1);
}

// --- checked writes ---

TEST_F(HalUl, SetPinValueWritesAnUnlinkedInputAndItReadsBack)
{
    ASSERT_EQ(hal_pin_s32_new("ul.in", HAL_IN, &p_->s[0], comp_), 0);
    ASSERT_EQ(hal_pin_bit_new("ul.io", HAL_IO, &p_->b[0], comp_), 0);
    union hal_value v = {};
    v.s = -12;
    EXPECT_EQ(hal_set_pin_value("ul.in", &v), 0);
    EXPECT_EQ(*p_->s[0], -12);
    struct hal_pin_info info;
    ASSERT_EQ(hal_find_pin("ul.in", &info), 0);
    EXPECT_EQ(info.value.s, -12);
    v = {};
    v.b = true;
    EXPECT_EQ(hal_set_pin_value("ul.io", &v), 0);
    EXPECT_TRUE(*p_->b[0]);
}

TEST_F(HalUl, SetPinValueRefusesAnUnknownPin)
{
    union hal_value v = {};
    MsgCapture msgs;
    EXPECT_EQ(hal_set_pin_value("ul.nosuch", &v), -ENOENT);
    EXPECT_THAT(msgs.text(), HasSubstr("pin 'ul.nosuch' does not exist"));
}

TEST_F(HalUl, SetPinValueRefusesAnOutputPin)
{
    ASSERT_EQ(hal_pin_float_new("ul.out", HAL_OUT, &p_->f[0], comp_), 0);
    union hal_value v = {};
    v.f = 1.0;
    MsgCapture msgs;
    EXPECT_EQ(hal_set_pin_value("ul.out", &v), -EPERM);
    EXPECT_THAT(msgs.text(), HasSubstr("pin 'ul.out' is an output"));
    EXPECT_EQ(*p_->f[0], 0.0);
}

TEST_F(HalUl, SetPinValueRefusesALinkedPin)
{
    ASSERT_EQ(hal_pin_float_new("ul.in", HAL_IN, &p_->f[0], comp_), 0);
    ASSERT_EQ(new_signal("ul.s", HAL_FLOAT), 0);
    ASSERT_EQ(hal_link("ul.in", "ul.s"), 0);
    union hal_value v = {};
    v.f = 1.0;
    MsgCapture msgs;
    EXPECT_EQ(hal_set_pin_value("ul.in", &v), -EBUSY);
    EXPECT_THAT(msgs.text(), HasSubstr("pin 'ul.in' is linked to signal 'ul.s'"));
    EXPECT_EQ(*p_->f[0], 0.0);
}

TEST_F(HalUl, SetParamValueWritesAReadWriteParameter)
{
    ASSERT_EQ(hal_param_float_new("ul.gain", HAL_RW, &p_->gain, comp_), 0);
    union hal_value v = {};
    v.f = 0.001;
    EXPECT_EQ(hal_set_param_value("ul.gain", &v), 0);
    EXPECT_EQ(p_->gain, 0.001);
    struct hal_param_info info;
    ASSERT_EQ(hal_find_param("ul.gain", &info), 0);
    EXPECT_EQ(info.value.f, 0.001);
}

TEST_F(HalUl, SetParamValueRefusesAReadOnlyOrUnknownParameter)
{
    ASSERT_EQ(hal_param_float_new("ul.ro", HAL_RO, &p_->ro, comp_), 0);
    union hal_value v = {};
    v.f = 3.0;
    MsgCapture msgs;
    EXPECT_EQ(hal_set_param_value("ul.ro", &v), -EPERM);
    EXPECT_THAT(msgs.text(), HasSubstr("parameter 'ul.ro' is read-only"));
    EXPECT_EQ(p_->ro, 0.0);
    EXPECT_EQ(hal_set_param_value("ul.nosuch", &v), -ENOENT);
    EXPECT_THAT(msgs.text(), HasSubstr("parameter 'ul.nosuch' does not exist"));
}

TEST_F(HalUl, SetSigValueReachesEveryLinkedReader)
{
    ASSERT_EQ(hal_pin_u32_new("ul.in0", HAL_IN, &p_->u[0], comp_), 0);
    ASSERT_EQ(hal_pin_u32_new("ul.in1", HAL_IN, &p_->u[1], comp_), 0);
    ASSERT_EQ(new_signal("ul.s", HAL_U32), 0);
    ASSERT_EQ(hal_link("ul.in0", "ul.s"), 0);
    ASSERT_EQ(hal_link("ul.in1", "ul.s"), 0);
    union hal_value v = {};
    v.u = 77;
    EXPECT_EQ(hal_set_sig_value("ul.s", &v), 0);
    EXPECT_EQ(*p_->u[0], 77u);
    EXPECT_EQ(*p_->u[1], 77u);
    struct hal_sig_info info;
    ASSERT_EQ(hal_find_sig("ul.s", &info), 0);
    EXPECT_EQ(info.value.u, 77u);
}

TEST_F(HalUl, SetSigValueIsAllowedWithOnlyIoPins)
{
    ASSERT_EQ(hal_pin_u32_new("ul.io", HAL_IO, &p_->u[0], comp_), 0);
    ASSERT_EQ(new_signal("ul.s", HAL_U32), 0);
    ASSERT_EQ(hal_link("ul.io", "ul.s"), 0);
    union hal_value v = {};
    v.u = 5;
    EXPECT_EQ(hal_set_sig_value("ul.s", &v), 0);
    EXPECT_EQ(*p_->u[0], 5u);
}

TEST_F(HalUl, SetSigValueRefusesASignalWithAWriterOrAnUnknownSignal)
{
    ASSERT_EQ(hal_pin_u32_new("ul.out", HAL_OUT, &p_->u[0], comp_), 0);
    ASSERT_EQ(new_signal("ul.s", HAL_U32), 0);
    ASSERT_EQ(hal_link("ul.out", "ul.s"), 0);
    union hal_value v = {};
    v.u = 5;
    MsgCapture msgs;
    EXPECT_EQ(hal_set_sig_value("ul.s", &v), -EPERM);
    EXPECT_THAT(msgs.text(), HasSubstr("signal 'ul.s' already has a writer"));
    EXPECT_EQ(*p_->u[0], 0u);
    EXPECT_EQ(hal_set_sig_value("ul.nosuch", &v), -ENOENT);
}

TEST_F(HalUl, ParamsLockRefusesEverySetWithEacces)
{
    ASSERT_EQ(hal_pin_s32_new("ul.in", HAL_IN, &p_->s[0], comp_), 0);
    ASSERT_EQ(hal_param_float_new("ul.gain", HAL_RW, &p_->gain, comp_), 0);
    ASSERT_EQ(new_signal("ul.s", HAL_BIT), 0);
    ASSERT_EQ(hal_set_lock(HAL_LOCK_PARAMS), 0);
    union hal_value v = {};
    MsgCapture msgs;
    v.s = 3;
    EXPECT_EQ(hal_set_pin_value("ul.in", &v), -EACCES);
    v.f = 3.0;
    EXPECT_EQ(hal_set_param_value("ul.gain", &v), -EACCES);
    v.b = true;
    EXPECT_EQ(hal_set_sig_value("ul.s", &v), -EACCES);
    EXPECT_THAT(msgs.text(), HasSubstr("HAL is locked (params): cannot set pins"));
    EXPECT_THAT(msgs.text(), HasSubstr("cannot set parameters"));
    EXPECT_THAT(msgs.text(), HasSubstr("cannot set signals"));
    EXPECT_EQ(*p_->s[0], 0);
    EXPECT_EQ(p_->gain, 0.0);
}

TEST_F(HalUl, OtherLocksDoNotRefuseSets)
{
    ASSERT_EQ(hal_param_float_new("ul.gain", HAL_RW, &p_->gain, comp_), 0);
    ASSERT_EQ(hal_set_lock(HAL_LOCK_ALL & ~HAL_LOCK_PARAMS), 0);
    union hal_value v = {};
    v.f = 3.0;
    EXPECT_EQ(hal_set_param_value("ul.gain", &v), 0);
    EXPECT_EQ(p_->gain, 3.0);
}

TEST_F(HalUl, MemoryUsageGrowsWithObjectsAndShrinksWhenTheyGo)
{
    unsigned long used0, total;
    ASSERT_EQ(hal_memory_usage(&used0, &total), 0);
    EXPECT_EQ(total, HAL_SEGMENT_SIZE_DEFAULT);
    EXPECT_GT(used0, 0u);
    EXPECT_LT(used0, total);
    int id = hal_init("ul.more");
    ASSERT_GT(id, 0);
    auto* pp = static_cast<UlPins*>(hal_malloc(sizeof(UlPins)));
    ASSERT_NE(pp, nullptr);
    for (int i = 0; i < 4; i++)
        ASSERT_EQ(hal_pin_float_newf(HAL_IN, &pp->f[i], id, "ul.more.%d", i), 0);
    unsigned long used1;
    ASSERT_EQ(hal_memory_usage(&used1, &total), 0);
    EXPECT_GE(used1, used0 + sizeof(UlPins) + 4 * sizeof(struct hal_pin_rec));
    ASSERT_EQ(hal_exit(id), 0);
    unsigned long used2;
    ASSERT_EQ(hal_memory_usage(&used2, &total), 0);
    EXPECT_EQ(used2, used0);
}

TEST_F(HalUl, ExitRefusesAnUnknownId)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_exit(9999), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("component id 9999 does not exist"));
}

TEST_F(HalUl, NoThreadsRunAndThereIsNoBasePeriodWithoutRealtimeCode)
{
    EXPECT_FALSE(hal_threads_running());
    EXPECT_EQ(hal_base_period(), 0);
}

}  // namespace
}  // namespace hal_test

namespace hal_test {
namespace {

// Issue 19, item 1: a process killed while it holds the HAL lock (a halcmd in the
// middle of a .hal file) used to hang every later HAL call, spinning forever.
TEST_F(HalUl, ALockHeldByADeadProcessIsTakenOverWithAWarning)
{
    pid_t child = fork();
    if (child == 0) {
        hal_lock();  // the mapping is shared with the parent
        _exit(0);    // dies holding it
    }
    ASSERT_GT(child, 0);
    int status;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_NE(hal_seg->mutex, 0UL);
    MsgCapture msgs;
    int old = rtapi_get_msg_level();
    rtapi_set_msg_level(RTAPI_MSG_WARN);
    EXPECT_EQ(hal_signal_new("after.dead.holder", HAL_BIT), 0);  // returns, not hangs
    rtapi_set_msg_level(old);
    sigs_.push_back("after.dead.holder");
    EXPECT_THAT(msgs.text(), HasSubstr("the HAL mutex was held by pid " + std::to_string(child)));
    EXPECT_THAT(msgs.text(), HasSubstr("which is gone: recovered"));
    EXPECT_EQ(hal_seg->mutex, 0UL);
}

}  // namespace
}  // namespace hal_test
