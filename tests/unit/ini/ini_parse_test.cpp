// SPDX-License-Identifier: GPL-2.0-or-later
// Lines, comments, sections, keys, repeated keys, continuation lines and carriage
// returns, as the 2.4-2.9 reader treats them (ini-and-launch.md 1.1).
#include <gtest/gtest.h>

#include "ini/ini_file.hpp"
#include "ini_of.hpp"

using hal::ini::IniFile;

namespace {

std::string error_of(std::string_view text)
{
    auto r = IniFile::parse(text, "m.ini");
    EXPECT_FALSE(r);
    return r ? "" : r.error().message;
}

}  // namespace

TEST(IniParse, KeyValueTrimmed)
{
    IniFile ini = ini_of("[S]\n  KEY  =   a value \t \nB=x\n");
    EXPECT_EQ(ini.find("S", "KEY"), "a value");
    EXPECT_EQ(ini.find("S", "B"), "x");
    EXPECT_EQ(ini.path(), "m.ini");
}

TEST(IniParse, CommentLinesOnlyAtLineStart)
{
    IniFile ini = ini_of("[S]\n# K = 1\n  ; K = 2\nK = value # note ; other\n");
    EXPECT_EQ(ini.find("S", "K"), "value # note ; other");   // no trailing comments
    EXPECT_EQ(ini.find_all("S", "K").size(), 1u);
}

TEST(IniParse, BlankLinesIgnored)
{
    IniFile ini = ini_of("\n\n[S]\n\n   \nK=1\n\n");
    EXPECT_EQ(ini.find("S", "K"), "1");
}

TEST(IniParse, NamesAreCaseSensitive)
{
    IniFile ini = ini_of("[Sec]\nKey = 1\n");
    EXPECT_EQ(ini.find("Sec", "Key"), "1");
    EXPECT_FALSE(ini.find("SEC", "Key"));
    EXPECT_FALSE(ini.find("Sec", "KEY"));
}

TEST(IniParse, SectionHeaderWithLeadingBlanksAndTrailingText)
{
    IniFile ini = ini_of("   [A] anything here\nK = 1\n");
    EXPECT_EQ(ini.find("A", "K"), "1");
}

TEST(IniParse, OrderOfSectionsDoesNotMatter)
{
    IniFile ini = ini_of("[B]\nK=b\n[A]\nK=a\n");
    EXPECT_EQ(ini.find("A", "K"), "a");
    EXPECT_EQ(ini.find("B", "K"), "b");
}

TEST(IniParse, OnlyTheFirstBlockOfASectionIsSearched)
{
    IniFile ini = ini_of("[A]\nK=1\n[B]\nX=2\n[A]\nK=3\nL=4\n");
    EXPECT_EQ(ini.find_all("A", "K"), std::vector<std::string>{"1"});
    EXPECT_FALSE(ini.find("A", "L"));
    ASSERT_EQ(ini.warnings().size(), 1u);
    EXPECT_EQ(ini.warnings()[0], "m.ini:5: second [A] block is never read (the first one is at m.ini:1)");
}

TEST(IniParse, UnterminatedHeaderEndsTheSection)
{
    IniFile ini = ini_of("[A]\nK=1\n[B\nL=2\n");
    EXPECT_EQ(ini.find("A", "K"), "1");
    EXPECT_FALSE(ini.find("A", "L"));
    EXPECT_FALSE(ini.find("B", "L"));
    ASSERT_GE(ini.warnings().size(), 1u);
    EXPECT_EQ(ini.warnings()[0], "m.ini:3: section header without ']': the lines after it belong to no section");
}

TEST(IniParse, KeysBeforeAnySectionAreNeverFound)
{
    IniFile ini = ini_of("K=1\n[A]\n");
    EXPECT_FALSE(ini.find("", "K"));
    ASSERT_EQ(ini.warnings().size(), 1u);
    EXPECT_EQ(ini.warnings()[0], "m.ini:1: key line outside any section is never read");
}

TEST(IniParse, KeyEndsAtBlankTabOrEquals)
{
    IniFile ini = ini_of("[S]\nA=1\nB\t= 2\nCD = 3\nE F = 4\n");
    EXPECT_EQ(ini.find("S", "A"), "1");
    EXPECT_EQ(ini.find("S", "B"), "2");
    EXPECT_EQ(ini.find("S", "CD"), "3");
    EXPECT_FALSE(ini.find("S", "C"));     // a prefix of a key is not the key
    EXPECT_EQ(ini.find("S", "E"), "4");   // the first word is the key
}

TEST(IniParse, ValueStartsAfterTheFirstEquals)
{
    IniFile ini = ini_of("[S]\nK = a = b\nE =\nQ = \"quoted\"\n");
    EXPECT_EQ(ini.find("S", "K"), "a = b");
    EXPECT_EQ(ini.find("S", "E"), "");        // present, empty
    EXPECT_EQ(ini.find("S", "Q"), "\"quoted\"");
}

TEST(IniParse, KeyLineWithoutEqualsIsNotFound)
{
    IniFile ini = ini_of("[S]\nK value\n=nokey\n");
    EXPECT_FALSE(ini.find("S", "K"));
    EXPECT_TRUE(ini.entries().empty());
}

TEST(IniParse, RepeatedKeysByOccurrence)
{
    IniFile ini = ini_of("[HAL]\nHALFILE = a.hal\nOTHER=x\nHALFILE = b.hal\nHALFILE = c.hal\n");
    EXPECT_EQ(ini.find("HAL", "HALFILE"), "a.hal");
    EXPECT_EQ(ini.find("HAL", "HALFILE", 2), "b.hal");
    EXPECT_EQ(ini.find("HAL", "HALFILE", 3), "c.hal");
    EXPECT_FALSE(ini.find("HAL", "HALFILE", 4));
    EXPECT_FALSE(ini.find("HAL", "HALFILE", 0));
    EXPECT_EQ(ini.find_all("HAL", "HALFILE"), (std::vector<std::string>{"a.hal", "b.hal", "c.hal"}));
    EXPECT_TRUE(ini.find_all("HAL", "NONE").empty());
}

TEST(IniParse, WhereNamesFileAndLine)
{
    IniFile ini = ini_of("[S]\n\nK=1\nK=2\n");
    EXPECT_EQ(ini.where("S", "K"), "m.ini:3");
    EXPECT_EQ(ini.where("S", "K", 2), "m.ini:4");
    EXPECT_EQ(ini.where("S", "X"), "m.ini");
}

TEST(IniParse, ContinuationAppendsTheNextLineAsIs)
{
    IniFile ini = ini_of("[S]\nK = one\\\n two\\\nthree\nL = 1\n");
    EXPECT_EQ(ini.find("S", "K"), "one twothree");
    EXPECT_EQ(ini.where("S", "K"), "m.ini:2");
    EXPECT_EQ(ini.where("S", "L"), "m.ini:5");
}

TEST(IniParse, ContinuationNeedsTheBackslashLast)
{
    IniFile ini = ini_of("[S]\nK = one\\ \nL = 2\n");
    EXPECT_EQ(ini.find("S", "K"), "one\\");
    EXPECT_EQ(ini.find("S", "L"), "2");
}

TEST(IniParse, ContinuationAtEndOfFileKeepsTheBackslash)
{
    IniFile ini = ini_of("[S]\nK = one\\");
    EXPECT_EQ(ini.find("S", "K"), "one\\");
}

TEST(IniParse, TwentyContinuationsAllowedNotMore)
{
    std::string ok = "[S]\nK = 0\\\n";
    for (int i = 1; i < 20; i++)
        ok += std::to_string(i % 10) + "\\\n";
    ok += "x\n";
    EXPECT_EQ(ini_of(ok).find("S", "K"), "01234567890123456789x");
    std::string bad = "[S]\nK = 0\\\n";
    for (int i = 1; i <= 20; i++)
        bad += "1\\\n";
    bad += "x\n";
    EXPECT_EQ(error_of(bad), "m.ini:2: more than 20 continuation lines (Too many backslash line extends)");
}

TEST(IniParse, DosLineEndingsAcceptedWithOneWarning)
{
    IniFile ini = ini_of("[S]\r\nK = v \r\nL=w\r\n");
    EXPECT_EQ(ini.find("S", "K"), "v");
    EXPECT_EQ(ini.find("S", "L"), "w");
    EXPECT_EQ(ini.warnings(), std::vector<std::string>{"m.ini: file contains DOS-style line endings"});
}

TEST(IniParse, LoneCarriageReturnIsAnError)
{
    EXPECT_EQ(error_of("[S]\nK = a\rb\n"), "m.ini:2: ambiguous carriage return (a CR not followed by LF)");
}

TEST(IniParse, EntriesKeepEverythingInOrder)
{
    IniFile ini = ini_of("[A]\nK=1\n[B]\nL=2\n[A]\nM=3\n");
    ASSERT_EQ(ini.entries().size(), 3u);
    EXPECT_EQ(ini.entries()[0].section, "A");
    EXPECT_EQ(ini.entries()[1].key, "L");
    EXPECT_EQ(ini.entries()[1].line, 4);
    EXPECT_TRUE(ini.entries()[1].reachable);
    EXPECT_FALSE(ini.entries()[2].reachable);
}
