// SPDX-License-Identifier: GPL-2.0-or-later
// hal_signal_param_rt_test.cpp - signals, linking rules (hal_signal_new(3hal)) and
// parameters (hal_param_new(3hal)) through the public API, realtime flavor.
#include "hal_rt_fixture.hpp"

namespace hal_test {
namespace {

using ::testing::HasSubstr;

class HalLink : public HalRt {
protected:
    void SetUp() override
    {
        HalRt::SetUp();
        ASSERT_EQ(hal_pin_float_new("rt.out", HAL_OUT, &pins_->f[0], comp_), 0);
        ASSERT_EQ(hal_pin_float_new("rt.out2", HAL_OUT, &pins_->f[1], comp_), 0);
        ASSERT_EQ(hal_pin_float_new("rt.in", HAL_IN, &pins_->f[2], comp_), 0);
        ASSERT_EQ(hal_pin_float_new("rt.in2", HAL_IN, &pins_->f[3], comp_), 0);
        ASSERT_EQ(hal_pin_s32_new("rt.io", HAL_IO, &pins_->s[0], comp_), 0);
        ASSERT_EQ(hal_pin_s32_new("rt.io2", HAL_IO, &pins_->s[1], comp_), 0);
        ASSERT_EQ(hal_pin_s32_new("rt.sout", HAL_OUT, &pins_->s[2], comp_), 0);
        ASSERT_EQ(new_signal("sf", HAL_FLOAT), 0);
        ASSERT_EQ(new_signal("sf2", HAL_FLOAT), 0);
        ASSERT_EQ(new_signal("ss", HAL_S32), 0);
    }
};

TEST_F(HalRt, SignalNewCreatesASignalOfEachType)
{
    for (hal_type_t t : {HAL_BIT, HAL_FLOAT, HAL_S32, HAL_U32}) {
        std::string n = "sig." + std::to_string(t);
        ASSERT_EQ(new_signal(n, t), 0);
        EXPECT_EQ(sig_rec(n)->type, t);
        EXPECT_EQ(hal_sig_value(sig_rec(n))->raw, 0u);
    }
}

TEST_F(HalRt, SignalNewRefusesAnInvalidType)
{
    MsgCapture msgs;
    EXPECT_EQ(new_signal("sig.bad", HAL_TYPE_UNSPECIFIED), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("signal 'sig.bad': invalid type"));
    EXPECT_EQ(sig_rec("sig.bad"), nullptr);
}

TEST_F(HalRt, SignalNewRefusesADuplicateName)
{
    ASSERT_EQ(new_signal("sig.dup", HAL_BIT), 0);
    EXPECT_EQ(new_signal("sig.dup", HAL_FLOAT), -EEXIST);
    EXPECT_EQ(sig_rec("sig.dup")->type, HAL_BIT);
}

TEST_F(HalRt, SignalNewRefusesABadName)
{
    EXPECT_EQ(new_signal("has space", HAL_BIT), -EINVAL);
    EXPECT_EQ(new_signal(std::string(HAL_NAME_LEN + 1, 's'), HAL_BIT), -EINVAL);
    EXPECT_EQ(new_signal(std::string(HAL_NAME_LEN, 's'), HAL_BIT), 0);
}

TEST_F(HalRt, SignalDeleteRefusesAnUnknownSignal)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_signal_delete("nosuch"), -ENOENT);
    EXPECT_THAT(msgs.text(), HasSubstr("signal 'nosuch' does not exist"));
}

TEST_F(HalLink, LinkAimsThePinAtTheSignalValue)
{
    ASSERT_EQ(hal_link("rt.in", "sf"), 0);
    EXPECT_EQ(pins_->f[2], &hal_sig_value(sig_rec("sf"))->f);
    EXPECT_EQ(sig_rec("sf")->readers, 1);
    hal_sig_value(sig_rec("sf"))->f = 4.25;
    EXPECT_EQ(*pins_->f[2], 4.25);
}

TEST_F(HalLink, AnOutputAndItsReadersShareTheValue)
{
    ASSERT_EQ(hal_link("rt.out", "sf"), 0);
    ASSERT_EQ(hal_link("rt.in", "sf"), 0);
    ASSERT_EQ(hal_link("rt.in2", "sf"), 0);
    *pins_->f[0] = -3.5;
    EXPECT_EQ(*pins_->f[2], -3.5);
    EXPECT_EQ(*pins_->f[3], -3.5);
    EXPECT_EQ(sig_rec("sf")->writers, 1);
    EXPECT_EQ(sig_rec("sf")->readers, 2);
}

TEST_F(HalLink, LinkRefusesATypeMismatch)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_link("rt.io", "sf"), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("type mismatch: pin 'rt.io' is s32 but signal 'sf' is float"));
    EXPECT_EQ(pin_rec("rt.io")->signal_off, 0u);
}

TEST_F(HalLink, LinkRefusesASecondOutputNamingTheWriter)
{
    ASSERT_EQ(hal_link("rt.out", "sf"), 0);
    MsgCapture msgs;
    EXPECT_EQ(hal_link("rt.out2", "sf"), -EPERM);
    EXPECT_THAT(msgs.text(), HasSubstr("signal 'sf' already has writer 'rt.out'"));
    EXPECT_EQ(sig_rec("sf")->writers, 1);
    EXPECT_EQ(pin_rec("rt.out2")->signal_off, 0u);
}

TEST_F(HalLink, LinkRefusesAnOutputOnASignalWithAnIoPin)
{
    ASSERT_EQ(hal_link("rt.io", "ss"), 0);
    EXPECT_EQ(hal_link("rt.sout", "ss"), -EPERM);
}

TEST_F(HalLink, LinkRefusesAnIoPinOnASignalWithAnOutput)
{
    ASSERT_EQ(hal_link("rt.sout", "ss"), 0);
    MsgCapture msgs;
    EXPECT_EQ(hal_link("rt.io", "ss"), -EPERM);
    EXPECT_THAT(msgs.text(), HasSubstr("already has writer 'rt.sout'"));
}

TEST_F(HalLink, LinkAllowsSeveralIoPins)
{
    ASSERT_EQ(hal_link("rt.io", "ss"), 0);
    ASSERT_EQ(hal_link("rt.io2", "ss"), 0);
    EXPECT_EQ(sig_rec("ss")->bidirs, 2);
    *pins_->s[0] = 42;
    EXPECT_EQ(*pins_->s[1], 42);
}

TEST_F(HalLink, LinkRefusesAPinAlreadyLinkedToAnotherSignal)
{
    ASSERT_EQ(hal_link("rt.in", "sf"), 0);
    MsgCapture msgs;
    EXPECT_EQ(hal_link("rt.in", "sf2"), -EBUSY);
    EXPECT_THAT(msgs.text(), HasSubstr("pin 'rt.in' is already linked to signal 'sf'"));
    EXPECT_EQ(sig_rec("sf2")->readers, 0);
}

TEST_F(HalLink, LinkingAgainToTheSameSignalChangesNothing)
{
    ASSERT_EQ(hal_link("rt.out", "sf"), 0);
    EXPECT_EQ(hal_link("rt.out", "sf"), 0);
    EXPECT_EQ(sig_rec("sf")->writers, 1);
}

TEST_F(HalLink, LinkRefusesAnUnknownPinOrSignal)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_link("rt.nopin", "sf"), -ENOENT);
    EXPECT_THAT(msgs.text(), HasSubstr("pin 'rt.nopin' does not exist"));
    EXPECT_EQ(hal_link("rt.in", "nosig"), -ENOENT);
    EXPECT_THAT(msgs.text(), HasSubstr("signal 'nosig' does not exist"));
}

TEST_F(HalLink, TheFirstLinkedPinGivesTheSignalItsValue)
{
    *pins_->f[2] = 7.5;   // setp rt.in 7.5, then net
    ASSERT_EQ(hal_link("rt.in", "sf"), 0);
    EXPECT_EQ(hal_sig_value(sig_rec("sf"))->f, 7.5);
    EXPECT_EQ(*pins_->f[2], 7.5);
}

TEST_F(HalLink, ALaterLinkedPinTakesTheSignalsValue)
{
    *pins_->f[2] = 7.5;
    *pins_->f[3] = 1.0;
    ASSERT_EQ(hal_link("rt.in", "sf"), 0);
    ASSERT_EQ(hal_link("rt.in2", "sf"), 0);
    EXPECT_EQ(*pins_->f[3], 7.5);
    EXPECT_EQ(hal_sig_value(sig_rec("sf"))->f, 7.5);
}

TEST_F(HalLink, UnlinkKeepsTheSignalsLastValueInThePin)
{
    ASSERT_EQ(hal_link("rt.out", "sf"), 0);
    ASSERT_EQ(hal_link("rt.in", "sf"), 0);
    *pins_->f[0] = 3.5;
    ASSERT_EQ(hal_unlink("rt.in"), 0);
    EXPECT_EQ(*pins_->f[2], 3.5);
    EXPECT_EQ(pins_->f[2], &hal_pin_dummy(pin_rec("rt.in"))->f);
    *pins_->f[0] = 9.0;
    EXPECT_EQ(*pins_->f[2], 3.5);
    EXPECT_EQ(sig_rec("sf")->readers, 0);
    EXPECT_EQ(sig_rec("sf")->writers, 1);
}

TEST_F(HalLink, UnlinkOfAWriterFreesTheWriterSlot)
{
    ASSERT_EQ(hal_link("rt.out", "sf"), 0);
    ASSERT_EQ(hal_unlink("rt.out"), 0);
    EXPECT_EQ(sig_rec("sf")->writers, 0);
    EXPECT_EQ(hal_link("rt.out2", "sf"), 0);
}

TEST_F(HalLink, UnlinkOfAnUnlinkedPinIsHarmless)
{
    EXPECT_EQ(hal_unlink("rt.in"), 0);
    EXPECT_EQ(pins_->f[2], &hal_pin_dummy(pin_rec("rt.in"))->f);
}

TEST_F(HalLink, UnlinkRefusesAnUnknownPin)
{
    MsgCapture msgs;
    EXPECT_EQ(hal_unlink("rt.nopin"), -ENOENT);
    EXPECT_THAT(msgs.text(), HasSubstr("pin 'rt.nopin' does not exist"));
}

TEST_F(HalLink, SignalDeleteUnlinksEveryPinAndKeepsTheirValues)
{
    ASSERT_EQ(hal_link("rt.out", "sf"), 0);
    ASSERT_EQ(hal_link("rt.in", "sf"), 0);
    ASSERT_EQ(hal_link("rt.in2", "sf"), 0);
    ASSERT_EQ(hal_link("rt.out2", "sf2"), 0);
    *pins_->f[0] = 1.25;
    ASSERT_EQ(hal_signal_delete("sf"), 0);
    EXPECT_EQ(sig_rec("sf"), nullptr);
    for (const char* p : {"rt.out", "rt.in", "rt.in2"}) {
        EXPECT_EQ(pin_rec(p)->signal_off, 0u) << p;
        EXPECT_EQ(hal_pin_dummy(pin_rec(p))->f, 1.25) << p;
    }
    EXPECT_EQ(pins_->f[2], &hal_pin_dummy(pin_rec("rt.in"))->f);
    EXPECT_EQ(*pins_->f[3], 1.25);
    EXPECT_NE(pin_rec("rt.out2")->signal_off, 0u);   // other signals untouched
    EXPECT_EQ(hal_signal_delete("sf"), -ENOENT);
}

TEST_F(HalLink, ADeletedSignalsNameCanBeUsedAgain)
{
    ASSERT_EQ(hal_link("rt.in", "sf"), 0);
    ASSERT_EQ(hal_signal_delete("sf"), 0);
    ASSERT_EQ(new_signal("sf", HAL_FLOAT), 0);
    EXPECT_EQ(hal_link("rt.in", "sf"), 0);
}

// --- parameters ---

TEST_F(HalRt, CreatesParametersOfEveryTypeReadOnlyAndReadWrite)
{
    auto* v = mem<ParamVals>();
    auto* w = mem<ParamVals>();
    ASSERT_EQ(hal_param_bit_new("rt.pb", HAL_RO, &v->b, comp_), 0);
    ASSERT_EQ(hal_param_float_new("rt.pf", HAL_RW, &v->f, comp_), 0);
    ASSERT_EQ(hal_param_s32_new("rt.ps", HAL_RO, &v->s, comp_), 0);
    ASSERT_EQ(hal_param_u32_new("rt.pu", HAL_RW, &v->u, comp_), 0);
    ASSERT_EQ(hal_param_new("rt.pg", HAL_U32, HAL_RO, (void*)&w->u, comp_), 0);
    EXPECT_EQ(param_rec("rt.pb")->type, HAL_BIT);
    EXPECT_EQ(param_rec("rt.pb")->dir, HAL_RO);
    EXPECT_EQ(param_rec("rt.pf")->type, HAL_FLOAT);
    EXPECT_EQ(param_rec("rt.pf")->dir, HAL_RW);
    EXPECT_EQ(param_rec("rt.ps")->type, HAL_S32);
    EXPECT_EQ(param_rec("rt.pu")->type, HAL_U32);
    EXPECT_EQ(seg_ptr(param_rec("rt.pg")->data_off), &w->u);
}

TEST_F(HalRt, ParamNewfFormatsTheName)
{
    auto* v = mem<ParamVals>();
    ASSERT_EQ(hal_param_float_newf(HAL_RW, &v->f, comp_, "rt.%d.%s", 2, "Pgain"), 0);
    ASSERT_EQ(hal_param_bit_newf(HAL_RW, &v->b, comp_, "rt.%d.b", 2), 0);
    ASSERT_EQ(hal_param_s32_newf(HAL_RW, &v->s, comp_, "rt.%d.s", 2), 0);
    ASSERT_EQ(hal_param_u32_newf(HAL_RW, &v->u, comp_, "rt.%d.u", 2), 0);
    EXPECT_NE(param_rec("rt.2.Pgain"), nullptr);
    EXPECT_NE(param_rec("rt.2.u"), nullptr);
    std::string tail(HAL_NAME_LEN - 2, 'p');
    EXPECT_EQ(hal_param_u32_newf(HAL_RW, &v->u, comp_, "rt.%s", tail.c_str()), -EINVAL);
}

TEST_F(HalRt, ParamNewRefusesABadTypeDirectionOrStorage)
{
    auto* v = mem<ParamVals>();
    hal_u32_t outside = 0;
    MsgCapture msgs;
    EXPECT_EQ(hal_param_new("rt.p", static_cast<hal_type_t>(7), HAL_RW, (void*)&v->u, comp_),
              -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("parameter 'rt.p': invalid type 7"));
    EXPECT_EQ(hal_param_new("rt.p", HAL_U32, static_cast<hal_param_dir_t>(HAL_IN), (void*)&v->u,
                            comp_),
              -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("parameter 'rt.p': invalid direction"));
    EXPECT_EQ(hal_param_u32_new("rt.p", HAL_RW, &outside, comp_), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("parameter 'rt.p': its data is not in HAL shared memory"));
    EXPECT_EQ(param_rec("rt.p"), nullptr);
}

TEST_F(HalRt, ParamNewRefusesADuplicateOrAnUnknownComponent)
{
    auto* v = mem<ParamVals>();
    ASSERT_EQ(hal_param_s32_new("rt.p", HAL_RW, &v->s, comp_), 0);
    EXPECT_EQ(hal_param_s32_new("rt.p", HAL_RW, &v->s, comp_), -EEXIST);
    MsgCapture msgs;
    EXPECT_EQ(hal_param_s32_new("rt.q", HAL_RW, &v->s, 9999), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("parameter 'rt.q': component id 9999 does not exist"));
}

TEST_F(HalRt, ParamSetWritesTheOwnersVariableEvenWhenReadOnly)
{
    auto* v = mem<ParamVals>();
    ASSERT_EQ(hal_param_bit_new("rt.pb", HAL_RO, &v->b, comp_), 0);
    ASSERT_EQ(hal_param_float_new("rt.pf", HAL_RO, &v->f, comp_), 0);
    ASSERT_EQ(hal_param_s32_new("rt.ps", HAL_RW, &v->s, comp_), 0);
    ASSERT_EQ(hal_param_u32_new("rt.pu", HAL_RW, &v->u, comp_), 0);
    EXPECT_EQ(hal_param_bit_set("rt.pb", 5), 0);
    EXPECT_EQ(hal_param_float_set("rt.pf", 0.125), 0);
    EXPECT_EQ(hal_param_s32_set("rt.ps", -77), 0);
    EXPECT_EQ(hal_param_u32_set("rt.pu", 4000000000ul), 0);
    EXPECT_EQ(v->b, true);
    EXPECT_EQ(v->f, 0.125);
    EXPECT_EQ(v->s, -77);
    EXPECT_EQ(v->u, 4000000000u);
    EXPECT_EQ(hal_param_bit_set("rt.pb", 0), 0);
    EXPECT_EQ(v->b, false);
    double d = 2.0;
    EXPECT_EQ(hal_param_set("rt.pf", HAL_FLOAT, &d), 0);
    EXPECT_EQ(v->f, 2.0);
}

TEST_F(HalRt, ParamSetRefusesAnUnknownNameOrTheWrongType)
{
    auto* v = mem<ParamVals>();
    ASSERT_EQ(hal_param_s32_new("rt.ps", HAL_RW, &v->s, comp_), 0);
    MsgCapture msgs;
    EXPECT_EQ(hal_param_s32_set("rt.nosuch", 1), -ENOENT);
    EXPECT_THAT(msgs.text(), HasSubstr("parameter 'rt.nosuch' does not exist"));
    EXPECT_EQ(hal_param_float_set("rt.ps", 1.0), -EINVAL);
    EXPECT_THAT(msgs.text(), HasSubstr("parameter 'rt.ps' is s32, not float"));
    EXPECT_EQ(v->s, 0);
}

}  // namespace
}  // namespace hal_test
