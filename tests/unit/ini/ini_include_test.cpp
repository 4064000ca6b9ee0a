// SPDX-License-Identifier: GPL-2.0-or-later
// load() and #INCLUDE (ini-and-launch.md 1.2, the 2.10 reader's rules): names next to
// the including file, from the cwd, absolute, ~ and $VAR; nesting, recursion, errors.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "ini/ini_file.hpp"

using hal::ini::IniFile;
namespace fs = std::filesystem;

namespace {

class IniInclude : public ::testing::Test {
protected:
    void SetUp() override
    {
        char tmpl[] = "/tmp/ini_test_XXXXXX";
        ASSERT_NE(::mkdtemp(tmpl), nullptr);
        dir_ = tmpl;
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text)
    {
        std::string p = dir_ + "/" + name;
        fs::create_directories(fs::path(p).parent_path());
        std::ofstream(p) << text;
        return p;
    }

    std::string dir_;
};

}  // namespace

TEST_F(IniInclude, LoadReadsAFile)
{
    auto r = IniFile::load(write("m.ini", "[S]\nK = 1\n"));
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(r->find("S", "K"), "1");
    EXPECT_EQ(r->path(), dir_ + "/m.ini");
    EXPECT_EQ(r->where("S", "K"), dir_ + "/m.ini:2");
}

TEST_F(IniInclude, MissingFileIsAnError)
{
    auto r = IniFile::load(dir_ + "/none.ini");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "cannot open inifile '" + dir_ + "/none.ini': No such file or directory");
}

TEST_F(IniInclude, IncludedLinesTakeTheLinesPlace)
{
    write("sub/joints.inc", "[JOINT_0]\nHOME = 5\n");
    auto r = IniFile::load(write("m.ini", "[S]\nA=1\n#INCLUDE sub/joints.inc\n[T]\nB=2\n"));
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(r->find("S", "A"), "1");
    EXPECT_EQ(r->find("JOINT_0", "HOME"), "5");
    EXPECT_EQ(r->where("JOINT_0", "HOME"), dir_ + "/sub/joints.inc:2");
    EXPECT_EQ(r->find("T", "B"), "2");
}

TEST_F(IniInclude, IncludedKeysJoinTheOpenSection)
{
    write("more.inc", "B = 2\n");
    auto r = IniFile::load(write("m.ini", "[S]\nA=1\n#INCLUDE more.inc\nC=3\n"));
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(r->find("S", "B"), "2");
    EXPECT_EQ(r->find("S", "C"), "3");
}

TEST_F(IniInclude, NestedIncludesRelativeToTheIncludingFile)
{
    write("a/b/last.inc", "[L]\nK=deep\n");
    write("a/mid.inc", "#INCLUDE b/last.inc\n");
    auto r = IniFile::load(write("m.ini", "#INCLUDE a/mid.inc\n"));
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(r->find("L", "K"), "deep");
}

TEST_F(IniInclude, AbsoluteHomeAndEnvironmentNames)
{
    std::string abs = write("abs.inc", "[A]\nK=abs\n");
    write("home/h.inc", "[H]\nK=home\n");
    write("env/e.inc", "[E]\nK=env\n");
    std::string old_home = std::getenv("HOME") ? std::getenv("HOME") : "";
    ::setenv("HOME", (dir_ + "/home").c_str(), 1);
    ::setenv("INI_TEST_DIR", (dir_ + "/env").c_str(), 1);
    auto r = IniFile::load(write("m.ini", "#INCLUDE " + abs + "\n#INCLUDE ~/h.inc\n#INCLUDE ${INI_TEST_DIR}/e.inc\n"));
    ::setenv("HOME", old_home.c_str(), 1);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(r->find("A", "K"), "abs");
    EXPECT_EQ(r->find("H", "K"), "home");
    EXPECT_EQ(r->find("E", "K"), "env");
}

TEST_F(IniInclude, ParseResolvesAgainstThePathsDirectory)
{
    write("p.inc", "[P]\nK=1\n");
    auto r = IniFile::parse("#INCLUDE p.inc\n", dir_ + "/virtual.ini");
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(r->find("P", "K"), "1");
}

TEST_F(IniInclude, OnlyUpperCaseAtColumnOneIsAnInclude)
{
    auto r = IniFile::load(write("m.ini", "[S]\n #INCLUDE x.inc\n#include x.inc\n#INCLUDEx.inc\nK=1\n"));
    ASSERT_TRUE(r) << r.error().message;   // all three are comments
    EXPECT_EQ(r->find("S", "K"), "1");
}

TEST_F(IniInclude, UnreadableIncludeIsAnError)
{
    auto r = IniFile::load(write("m.ini", "[S]\n#INCLUDE gone.inc\n"));
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, dir_ + "/m.ini:2: #INCLUDE: cannot open inifile '" + dir_ +
                                     "/gone.inc': No such file or directory");
}

TEST_F(IniInclude, IncludeWithoutNameIsAnError)
{
    auto r = IniFile::load(write("m.ini", "#INCLUDE   \n"));
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, dir_ + "/m.ini:1: #INCLUDE without a file name");
}

TEST_F(IniInclude, UnsetVariableIsAnError)
{
    ::unsetenv("INI_TEST_UNSET");
    auto r = IniFile::load(write("m.ini", "#INCLUDE $INI_TEST_UNSET/x.inc\n"));
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message,
              dir_ + "/m.ini:1: environment variable 'INI_TEST_UNSET' in #INCLUDE name is not set");
}

TEST_F(IniInclude, RecursionIsAnError)
{
    write("a.inc", "#INCLUDE b.inc\n");
    write("b.inc", "\n#INCLUDE a.inc\n");
    auto r = IniFile::load(write("m.ini", "#INCLUDE a.inc\n"));
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, dir_ + "/b.inc:2: #INCLUDE 'a.inc' includes itself (recursion)");
}

TEST_F(IniInclude, SixteenLevelsAllowedNotMore)
{
    for (int i = 1; i <= 17; i++)
        write("l" + std::to_string(i) + ".inc",
              i < 17 ? "#INCLUDE l" + std::to_string(i + 1) + ".inc\n" : "[D]\nK=1\n");
    auto deep = IniFile::load(write("m.ini", "#INCLUDE l1.inc\n"));   // 17 levels
    ASSERT_FALSE(deep);
    EXPECT_EQ(deep.error().message, dir_ + "/l16.inc:1: #INCLUDE nested more than 16 levels deep");
    auto ok = IniFile::load(write("n.ini", "#INCLUDE l2.inc\n"));     // 16 levels
    ASSERT_TRUE(ok) << ok.error().message;
    EXPECT_EQ(ok->find("D", "K"), "1");
}

TEST_F(IniInclude, ErrorsInsideAnIncludedFileNameIt)
{
    write("bad.inc", "[S]\nK = a\rb\n");
    auto r = IniFile::load(write("m.ini", "#INCLUDE bad.inc\n"));
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, dir_ + "/bad.inc:2: ambiguous carriage return (a CR not followed by LF)");
}
