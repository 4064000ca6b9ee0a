// SPDX-License-Identifier: GPL-2.0-or-later
// What a launch does, read from the INI file: programs and their arguments, HALFILE
// lookup (LIB:, absolute, -H dirs, INI dir, library), display forms, errors.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "plan.hpp"

using namespace hal::launcher;
using hal::ini::IniFile;
using V = std::vector<std::string>;
namespace fs = std::filesystem;

namespace {

class Plan_ : public ::testing::Test {
protected:
    void SetUp() override
    {
        char tmpl[] = "/tmp/launcher_test_XXXXXX";
        ASSERT_NE(::mkdtemp(tmpl), nullptr);
        dir_ = tmpl;
        fs::create_directories(dir_ + "/lib");
        fs::create_directories(dir_ + "/h");
        search_ = {{dir_ + "/h"}, dir_ + "/lib"};
    }
    void TearDown() override { fs::remove_all(dir_); }
    void touch(const std::string& rel) { std::ofstream(dir_ + "/" + rel) << "\n"; }
    hal::Result<Plan> plan(const std::string& text)
    {
        auto ini = IniFile::parse(text, dir_ + "/m.ini");
        EXPECT_TRUE(ini);
        return make_plan(*ini, search_);
    }

    std::string dir_;
    Search search_;
};

}  // namespace

TEST_F(Plan_, ProgramsGetIniArguments)
{
    auto p = plan("[TASK]\nTASK = milltask\n[HAL]\nHALUI = halui\n");
    ASSERT_TRUE(p) << p.error().message;
    std::string ini = dir_ + "/m.ini";
    EXPECT_EQ(p->task, (V{"milltask", "-ini", ini}));
    EXPECT_EQ(p->io, (V{"io", "-ini", ini}));   // [EMCIO]EMCIO defaults to io
    EXPECT_EQ(p->halui, (V{"halui", "-ini", ini}));
    EXPECT_EQ(p->ini_dir, dir_);
}

TEST_F(Plan_, EmptyEmcioMeansNoIoProcess)
{
    auto p = plan("[TASK]\nTASK = milltask\n[EMCIO]\nEMCIO =\n");
    ASSERT_TRUE(p);
    EXPECT_TRUE(p->io.empty());
    EXPECT_TRUE(p->halui.empty());
}

TEST_F(Plan_, TaskIsRequired)
{
    EXPECT_EQ(plan("[EMC]\n").error().message,
              dir_ + "/m.ini: [TASK]TASK is not set: name the task program (milltask)");
}

TEST_F(Plan_, HalfileLookupOrder)
{
    touch("h/both.hal");
    touch("both.hal");
    touch("here.hal");
    touch("here2.hal");
    touch("lib/here2.hal");
    touch("lib/onlylib.hal");
    touch("lib/core.hal");
    auto p = plan("[TASK]\nTASK=t\n[HAL]\nHALFILE = both.hal\nHALFILE = here.hal\nHALFILE = here2.hal\n"
                  "HALFILE = onlylib.hal\nHALFILE = LIB:core.hal\nHALFILE = " + dir_ + "/here.hal\n"
                  "HALFILE = x.tcl a b\n");
    ASSERT_FALSE(p);   // x.tcl does not exist
    touch("x.tcl");
    p = plan("[TASK]\nTASK=t\n[HAL]\nHALFILE = both.hal\nHALFILE = here.hal\nHALFILE = here2.hal\n"
             "HALFILE = onlylib.hal\nHALFILE = LIB:core.hal\nHALFILE = " + dir_ + "/here.hal\n"
             "HALFILE = x.tcl a b\n");
    ASSERT_TRUE(p) << p.error().message;
    ASSERT_EQ(p->halfiles.size(), 7u);
    EXPECT_EQ(p->halfiles[0].path, dir_ + "/h/both.hal");     // -H first
    EXPECT_EQ(p->halfiles[1].path, dir_ + "/here.hal");       // then the INI dir
    EXPECT_EQ(p->halfiles[2].path, dir_ + "/here2.hal");      // before the library
    EXPECT_EQ(p->halfiles[3].path, dir_ + "/lib/onlylib.hal");
    EXPECT_EQ(p->halfiles[4].path, dir_ + "/lib/core.hal");
    EXPECT_EQ(p->halfiles[5].path, dir_ + "/here.hal");
    EXPECT_TRUE(p->halfiles[6].is_tcl);
    EXPECT_EQ(p->halfiles[6].args, (V{"a", "b"}));
    EXPECT_EQ(p->halfiles[1].where, dir_ + "/m.ini:5");
}

TEST_F(Plan_, LibNamesOnlyInTheLibrary)
{
    touch("core.hal");
    auto p = plan("[TASK]\nTASK=t\n[HAL]\nHALFILE = LIB:core.hal\n");
    ASSERT_FALSE(p);
    EXPECT_EQ(p.error().message, dir_ + "/m.ini:4: [HAL]HALFILE 'LIB:core.hal' not found in the HAL library " +
                                     dir_ + "/lib");
}

TEST_F(Plan_, MissingHalfileNamesTheSearch)
{
    auto p = plan("[TASK]\nTASK=t\n[HAL]\nHALFILE = none.hal\n");
    ASSERT_FALSE(p);
    EXPECT_EQ(p.error().message, dir_ + "/m.ini:4: [HAL]HALFILE 'none.hal' not found (searched " + dir_ + "/h, " +
                                     dir_ + ", " + dir_ + "/lib)");
}

TEST_F(Plan_, HalcmdTwopassShutdown)
{
    touch("sd.hal");
    auto p = plan("[TASK]\nTASK=t\n[HAL]\nTWOPASS = on\nHALCMD = setp a 1\nHALCMD = net b c\nSHUTDOWN = sd.hal\n");
    ASSERT_TRUE(p);
    EXPECT_TRUE(p->twopass);
    EXPECT_EQ(p->halcmds, (V{"setp a 1", "net b c"}));
    EXPECT_EQ(p->halcmd_where[1], dir_ + "/m.ini:6");
    EXPECT_EQ(p->shutdown, dir_ + "/sd.hal");
    EXPECT_FALSE(plan("[TASK]\nTASK=t\n[HAL]\nTWOPASS =\n")->twopass);
}

TEST_F(Plan_, Applications)
{
    auto p = plan("[TASK]\nTASK=t\n[APPLICATIONS]\nDELAY = 1.5\nAPP = ./tool -x\nAPP = /bin/true\nAPP = sleep 1\n");
    ASSERT_TRUE(p);
    EXPECT_DOUBLE_EQ(p->app_delay, 1.5);
    ASSERT_EQ(p->apps.size(), 3u);
    EXPECT_EQ(p->apps[0].argv, (V{dir_ + "/tool", "-x"}));
    EXPECT_EQ(p->apps[1].argv, (V{"/bin/true"}));
    EXPECT_EQ(p->apps[2].argv, (V{"sleep", "1"}));   // PATH
    EXPECT_FALSE(plan("[TASK]\nTASK=t\n[APPLICATIONS]\nDELAY = -1\n"));
}

TEST_F(Plan_, DisplayForms)
{
    std::string ini = dir_ + "/m.ini";
    EXPECT_EQ(plan("[TASK]\nTASK=t\n")->display, DisplayKind::none);
    EXPECT_EQ(plan("[TASK]\nTASK=t\n[DISPLAY]\nDISPLAY = dummy\n")->display, DisplayKind::dummy);
    auto rsh = plan("[TASK]\nTASK=t\n[DISPLAY]\nDISPLAY = emcrsh -p 5008\n");
    EXPECT_EQ(rsh->display_program.argv, (V{"emcrsh", "-p", "5008", "--", "-ini", ini}));
    auto gui = plan("[TASK]\nTASK=t\n[DISPLAY]\nDISPLAY = mygui --big\n");
    EXPECT_EQ(gui->display, DisplayKind::program);
    EXPECT_EQ(gui->display_program.argv, (V{"mygui", "-ini", ini, "--big"}));
}

TEST(SplitWords, BlanksAndTabs)
{
    EXPECT_EQ(split_words("  a\tb  c "), (V{"a", "b", "c"}));
    EXPECT_TRUE(split_words(" \t ").empty());
}
