// SPDX-License-Identifier: GPL-2.0-or-later
// input_text_test - bytes halcmd accepts in a line, bounded reading with read errors
// reported, and messages that never carry raw control bytes (issue 19, items 4, 5, 9).
#include "input_text.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace {

using hal::halcmd::check_line_text;
using hal::halcmd::LineReader;
using hal::halcmd::max_line_bytes;
using hal::halcmd::printable;

TEST(CheckLineText, PlainTextTabsAndUtf8Pass)
{
    EXPECT_TRUE(check_line_text("setp siggen.0.offset 2"));
    EXPECT_TRUE(check_line_text("net a\tb  # caf\xc3\xa9"));
    EXPECT_TRUE(check_line_text("echo crlf\r"));  // a CRLF file
    EXPECT_TRUE(check_line_text(""));
}

TEST(CheckLineText, NulAndControlCharactersAreErrorsWithTheirColumn)
{
    auto r = check_line_text(std::string_view("setp siggen.0.offset 2\0" "5", 24));
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "a NUL byte at column 23 (a .hal line is text: no NUL or control "
                                 "characters but tab)");
    r = check_line_text("echo \x1b[2J");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "control character \\x1b at column 6 (a .hal line is text: no "
                                 "NUL or control characters but tab)");
    EXPECT_FALSE(check_line_text("a\x7f"));
    EXPECT_FALSE(check_line_text("a\rb"));  // a carriage return inside the line
}

TEST(Printable, EscapesControlsAndInvalidUtf8Only)
{
    EXPECT_EQ(printable("pin 'a.b' x"), "pin 'a.b' x");
    EXPECT_EQ(printable("caf\xc3\xa9 \xe2\x82\xac"), "caf\xc3\xa9 \xe2\x82\xac");
    EXPECT_EQ(printable("\x1b[31mred"), "\\x1b[31mred");
    EXPECT_EQ(printable(std::string_view("a\0b", 3)), "a\\x00b");
    EXPECT_EQ(printable("\x9b" "2J"), "\\x9b2J");           // a lone 8-bit CSI
    EXPECT_EQ(printable("\xc2\x9b" "2J"), "\\xc2\\x9b2J");  // C1 CSI encoded in UTF-8
    EXPECT_EQ(printable("\xc3"), "\\xc3");                  // cut sequence
    EXPECT_EQ(printable("a\tb\x7f"), "a\tb\\x7f");
}

// Every line of 'text' (through fmemopen), and the reader's error message if any.
struct ReadAll {
    std::vector<std::string> lines;
    std::string error;
};

ReadAll read_all(std::string text)
{
    ReadAll out;
    FILE* f = fmemopen(text.data(), text.size(), "r");
    if (!f)
        return out;
    LineReader reader(f);
    std::string line;
    while (reader.next(line))
        out.lines.push_back(line);
    if (reader.error())
        out.error = reader.error()->message;
    std::fclose(f);
    return out;
}

TEST(LineReader, SplitsLinesAndKeepsALastLineWithoutNewline)
{
    auto r = read_all("a\n\nb c\nlast");
    EXPECT_EQ(r.lines, (std::vector<std::string>{"a", "", "b c", "last"}));
    EXPECT_EQ(r.error, "");
}

TEST(LineReader, AnOverlongLineIsAnErrorAndStopsReading)
{
    auto r = read_all("ok\n" + std::string(max_line_bytes + 10, 'x') + "\nnever\n");
    EXPECT_EQ(r.lines, std::vector<std::string>{"ok"});
    EXPECT_EQ(r.error, "line longer than 65536 bytes; stopped reading");
}

TEST(LineReader, ADirectoryIsAReadErrorNotAnEmptyFile)
{
    FILE* f = std::fopen("/", "r");
    ASSERT_NE(f, nullptr);
    LineReader reader(f);
    std::string line;
    EXPECT_FALSE(reader.next(line));
    ASSERT_NE(reader.error(), nullptr);
    EXPECT_EQ(reader.error()->message, "cannot read: Is a directory");
    std::fclose(f);
}

}  // namespace
