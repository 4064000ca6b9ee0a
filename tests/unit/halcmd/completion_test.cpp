// SPDX-License-Identifier: GPL-2.0-or-later
// completion_test.cpp - tab-completion candidates for each argument position,
// computed from a hand-made HAL snapshot.
#include <gtest/gtest.h>

#include <cstring>

#include "completion.hpp"

using namespace hal::halcmd;
using V = std::vector<std::string>;

namespace {

void set_name(char* dst, const char* src)
{
    std::strncpy(dst, src, HAL_NAME_LEN);
    dst[HAL_NAME_LEN] = '\0';
}

hal_pin_info pin(const char* name, hal_type_t type, hal_pin_dir_t dir, const char* sig = "")
{
    hal_pin_info p{};
    set_name(p.name, name);
    p.type = type;
    p.dir = dir;
    set_name(p.signal, sig);
    return p;
}

hal_param_info param(const char* name, hal_param_dir_t dir)
{
    hal_param_info p{};
    set_name(p.name, name);
    p.type = HAL_S32;
    p.dir = dir;
    return p;
}

hal_sig_info sig(const char* name, hal_type_t type, int writers)
{
    hal_sig_info s{};
    set_name(s.name, name);
    s.type = type;
    s.writers = writers;
    return s;
}

class Completing : public ::testing::Test {
protected:
    void SetUp() override
    {
        snap.pins = {pin("and2.0.in0", HAL_BIT, HAL_IN), pin("and2.0.in1", HAL_BIT, HAL_IN, "b"),
                     pin("and2.0.out", HAL_BIT, HAL_OUT, "b2"), pin("not.0.in", HAL_BIT, HAL_IN),
                     pin("not.0.out", HAL_BIT, HAL_OUT), pin("siggen.0.sine", HAL_FLOAT, HAL_OUT)};
        snap.params = {param("and2.0.tmax", HAL_RW), param("and2.0.time", HAL_RO)};
        snap.sigs = {sig("b", HAL_BIT, 0), sig("b2", HAL_BIT, 1), sig("f", HAL_FLOAT, 0)};
        hal_funct_info f{};
        set_name(f.name, "and2.0");
        f.users = 1;
        hal_funct_info g{};
        set_name(g.name, "not.0");
        snap.functs = {f, g};
        ThreadEntry fast{};
        set_name(fast.info.name, "fast");
        fast.functs = {"and2.0"};
        ThreadEntry slow{};
        set_name(slow.info.name, "slow");
        snap.threads = {fast, slow};
        hal_comp_info rt{};
        set_name(rt.name, "and2");
        set_name(rt.module, "and2");
        rt.is_realtime = true;
        hal_comp_info user{};
        set_name(user.name, "ui");
        snap.comps = {rt, user};
        src.hal = &snap;
        src.commands = {"addf", "net", "newsig", "setp", "sets", "show"};
        src.modules = {"and2", "not", "or2"};
    }
    V complete_(std::string_view line) { return complete(line, src).candidates; }

    Snapshot snap;
    CompletionSources src;
};

}  // namespace

TEST_F(Completing, CommandNamesAtLineStart)
{
    EXPECT_EQ(complete_("se"), (V{"setp", "sets"}));
    EXPECT_EQ(complete_("n"), (V{"net", "newsig"}));
    EXPECT_EQ(complete_("").size(), src.commands.size());
}

TEST_F(Completing, SetpOffersWritableParamsAndUnlinkedInputPins)
{
    EXPECT_EQ(complete_("setp and2.0."), (V{"and2.0.in0", "and2.0.tmax"}));
    EXPECT_TRUE(complete_("setp and2.0.in0 ").empty());
}

TEST_F(Completing, NetFirstArgumentIsASignal)
{
    EXPECT_EQ(complete_("net "), (V{"b", "b2", "f"}));
}

TEST_F(Completing, NetPinsMatchSignalTypeAndSkipLinkedAndSecondWriters)
{
    // b2 already has a writer: OUT pins are not offered, linked pins never are.
    EXPECT_EQ(complete_("net b2 "), (V{"and2.0.in0", "not.0.in"}));
    // new signal: the first pin sets the type; after an OUT pin no other OUT pin fits.
    EXPECT_EQ(complete_("net new not.0.out => "), (V{"and2.0.in0", "not.0.in"}));
    EXPECT_EQ(complete_("net f "), (V{"siggen.0.sine"}));
}

TEST_F(Completing, AddfFunctThenThread)
{
    EXPECT_EQ(complete_("addf "), (V{"and2.0", "not.0"}));
    EXPECT_EQ(complete_("addf not.0 "), (V{"fast", "slow"}));
}

TEST_F(Completing, DelfOnlyFunctsOnThreads)
{
    EXPECT_EQ(complete_("delf "), (V{"and2.0"}));
    EXPECT_EQ(complete_("delf and2.0 "), (V{"fast"}));
}

TEST_F(Completing, LoadrtModulesAndUnloadrtLoadedOnes)
{
    EXPECT_EQ(complete_("loadrt o"), (V{"or2"}));
    EXPECT_EQ(complete_("unloadrt "), (V{"all", "and2"}));
}

TEST_F(Completing, UserComponentCommands)
{
    EXPECT_EQ(complete_("unloadusr "), (V{"all", "ui"}));
    EXPECT_EQ(complete_("waitusr "), (V{"ui"}));
}

TEST_F(Completing, ShowItemsThenNames)
{
    EXPECT_EQ(complete_("show p"), (V{"param", "pin"}));
    EXPECT_EQ(complete_("show sig b"), (V{"b", "b2"}));
    EXPECT_EQ(complete_("show thread "), (V{"fast", "slow"}));
}

TEST_F(Completing, SetsOnlyUndrivenSignals)
{
    EXPECT_EQ(complete_("sets "), (V{"b", "f"}));
}

TEST_F(Completing, LinkpsPinThenSignalOfItsType)
{
    EXPECT_EQ(complete_("linkps siggen.0.sine "), (V{"f"}));
    EXPECT_EQ(complete_("linksp b "), (V{"and2.0.in0", "not.0.in", "not.0.out"}));
}

TEST_F(Completing, NewsigTypes)
{
    EXPECT_EQ(complete_("newsig x "), (V{"bit", "float", "s32", "u32"}));
}

TEST_F(Completing, SourceUsesFileNames)
{
    EXPECT_TRUE(complete("source fo", src).filenames);
    EXPECT_FALSE(complete("setp fo", src).filenames);
}

TEST_F(Completing, LockLevels)
{
    EXPECT_EQ(complete_("unlock p"), (V{"params"}));
}
