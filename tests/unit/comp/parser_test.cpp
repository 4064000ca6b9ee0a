// SPDX-License-Identifier: GPL-2.0-or-later
// parser_test.cpp - the .comp grammar of LANGUAGE.md and its error messages.
#include <gtest/gtest.h>

#include "parser.hpp"

using namespace hal::comp;

namespace {

Component parse_ok(const std::string& text)
{
    std::string warnings;
    auto c = parse_comp(text, "t.comp", &warnings);
    EXPECT_TRUE(c.has_value()) << (c ? "" : c.error().message);
    return c ? *c : Component{};
}

std::string parse_error(const std::string& text)
{
    auto c = parse_comp(text, "mything.comp");
    EXPECT_FALSE(c.has_value());
    return c ? "" : c.error().message;
}

}  // namespace

TEST(CompParser, ReadsPinsParamsFunctionsAndCode)
{
    Component c = parse_ok(
        "component lowpass \"Low-pass filter\";\n"
        "pin in float in;\n"
        "pin out float out \"the output\";\n"
        "param rw float gain = 0.5;\n"
        "function _;\n"
        "license \"GPL\";\n"
        ";;\n"
        "FUNCTION(_) { out = in; }\n");
    EXPECT_EQ(c.name, "lowpass");
    EXPECT_EQ(c.doc, "Low-pass filter");
    ASSERT_EQ(c.items.size(), 3u);
    EXPECT_TRUE(c.items[0].is_pin);
    EXPECT_EQ(c.items[0].dir, Dir::In);
    EXPECT_EQ(c.items[1].doc, "the output");
    EXPECT_FALSE(c.items[2].is_pin);
    EXPECT_EQ(c.items[2].dir, Dir::Rw);
    EXPECT_EQ(c.items[2].default_value, "0.5");
    ASSERT_EQ(c.functions.size(), 1u);
    EXPECT_TRUE(c.functions[0].fp);  // fp is the default
    EXPECT_EQ(c.license, "GPL");
    EXPECT_EQ(c.code, "FUNCTION(_) { out = in; }\n");
    EXPECT_EQ(c.code_line, 8);
}

TEST(CompParser, ReadsArraysWithPersonalityAndConditions)
{
    Component c = parse_ok(
        "component logic;\n"
        "pin in bit in-##[16 : personality & 0xff] \"inputs\";\n"
        "pin out bit and if personality & 0x100;\n"
        "option personality yes;\n"
        "function _ nofp;\n"
        "license \"GPL\";\n;;\n");
    ASSERT_EQ(c.items.size(), 2u);
    EXPECT_EQ(c.items[0].array_size, 16);
    EXPECT_EQ(c.items[0].array_count, "personality & 0xff");
    EXPECT_EQ(c.items[0].doc, "inputs");
    EXPECT_EQ(c.items[1].condition, "personality & 0x100");
    EXPECT_FALSE(c.functions[0].fp);
    EXPECT_TRUE(c.has_personality());
}

TEST(CompParser, ReadsVariablesOptionsModparamsAndTripleQuotedText)
{
    Component c = parse_ok(
        "// comment\ncomponent x; /* another */\n"
        "variable double last = 0.25;\n"
        "variable int *ptr;\n"
        "variable int hist[3];\n"
        "option singleton yes;\n"
        "option extra_setup;\n"
        "modparam int depth = 5 \"how deep\";\n"
        "include <rtapi_string.h>;\n"
        "description \"\"\"two\nlines \\\"quoted\\\"\"\"\";\n"
        "pin out s32 y = -3;\n"
        "function go;\n"
        "license \"GPL\";\n;;\n");
    ASSERT_EQ(c.variables.size(), 3u);
    EXPECT_EQ(c.variables[0].default_value, "0.25");
    EXPECT_EQ(c.variables[1].stars, "*");
    EXPECT_EQ(c.variables[2].array_size, 3);
    EXPECT_TRUE(c.is_singleton());
    EXPECT_TRUE(c.option_on("extra_setup"));
    ASSERT_EQ(c.modparams.size(), 1u);
    EXPECT_EQ(c.modparams[0].default_value, "5");
    EXPECT_EQ(c.modparams[0].doc, "how deep");
    EXPECT_EQ(c.includes.at(0), "<rtapi_string.h>");
    EXPECT_EQ(c.description, "two\nlines \"quoted\"");
    EXPECT_EQ(c.items[0].default_value, "-3");
}

TEST(CompParser, NamesTheLineOfAMissingSemicolon)
{
    EXPECT_EQ(parse_error("component mything;\n\npin in float in0\npin out bit x;\n"),
              "mything.comp:3: expected ';' after pin declaration");
    EXPECT_EQ(parse_error("component mything;\nfunction _ fp\n;;\n"),
              "mything.comp:2: expected ';' after function declaration");
}

TEST(CompParser, RejectsBadWordsNamingThem)
{
    EXPECT_EQ(parse_error("component m;\npin inout float x;\n"),
              "mything.comp:2: expected the pin direction in, out or io, found 'inout'");
    EXPECT_EQ(parse_error("component m;\nparam w float x;\n"),
              "mything.comp:2: expected the param direction r or rw, found 'w'");
    EXPECT_EQ(parse_error("component m;\npin in double x;\n"),
              "mything.comp:2: expected the pin type bit, float, s32, u32, s64 or u64, found 'double'");
    EXPECT_EQ(parse_error("component m;\npins in bit x;\n").substr(0, 40),
              "mything.comp:2: unknown declaration 'pin");
    EXPECT_EQ(parse_error("pin in bit x;\n"),
              "mything.comp:1: expected 'component NAME;' as the first declaration, found 'pin'");
    EXPECT_EQ(parse_error(""), "mything.comp:1: empty file: expected 'component NAME;'");
    EXPECT_EQ(parse_error("component m;\npin in bit x = @;\n"),
              "mything.comp:2: bad default value for pin 'x', found '@;' (expected a number, TRUE, "
              "FALSE or a C name)");
    EXPECT_EQ(parse_error("component m;\nmodparam float x;\n"),
              "mything.comp:2: expected the modparam type int, long, string or dummy, found 'float'");
}

TEST(CompParser, RejectsUnterminatedStringsAndComments)
{
    EXPECT_EQ(parse_error("component m \"abc\n;\n"),
              "mything.comp:1: unterminated string (use \"\"\"...\"\"\" for text over several lines)");
    EXPECT_EQ(parse_error("component m;\n/* x\n"), "mything.comp:2: unterminated /* comment");
}

TEST(CompParser, ChecksArrayNames)
{
    EXPECT_EQ(parse_error("component m;\npin out bit out[8];\nfunction _;\n;;\n"),
              "mything.comp:2: pin 'out' is an array but its name has no '#' for the index");
    EXPECT_EQ(parse_error("component m;\npin out bit out-#;\nfunction _;\n;;\n"),
              "mything.comp:2: pin 'out-#' has '#' in its name but no array size ([N])");
    EXPECT_EQ(parse_error("component m;\npin out bit o-#-#[2];\nfunction _;\n;;\n"),
              "mything.comp:2: pin 'o-#-#' has more than one block of '#'");
    EXPECT_EQ(parse_error("component m;\npin out bit o-#[0];\nfunction _;\n;;\n"),
              "mything.comp:2: array size of pin 'o-#' must be a number 1..1000, found '0'");
}

TEST(CompParser, ChecksNamesAndFunctions)
{
    EXPECT_EQ(parse_error("component m;\npin in bit a-b;\npin in bit a_b;\nfunction _;\n;;\n"),
              "mything.comp:3: pin 'a_b': C name 'a_b' already used on line 2");
    EXPECT_EQ(parse_error("component m;\npin in bit period;\nfunction _;\n;;\n"),
              "mything.comp:2: pin 'period': the C name 'period' is reserved by the generated "
              "code; rename it (e.g. 'period_')");
    EXPECT_EQ(parse_error("component m;\nfunction _;\nfunction b;\n;;\n"),
              "mything.comp:2: function '_' must be the only function of the component");
    EXPECT_EQ(parse_error("component m;\npin in bit x;\n;;\n"),
              "mything.comp:1: realtime component 'm' needs at least one 'function' declaration");
    EXPECT_EQ(parse_error("component m;\noption userspace;\nfunction f;\n;;\n"),
              "mything.comp:3: a userspace component has no functions: write user_mainloop() instead");
    EXPECT_EQ(parse_error("component m;\noption default_count 0;\nfunction f;\n;;\n"),
              "mything.comp:2: option default_count must be 1..64, not '0'");
}

TEST(CompParser, WarnsAboutUnknownOptionsAndMissingLicense)
{
    std::string warnings;
    auto c = parse_comp("component m;\noption frobnicate;\nfunction f;\n;;\n", "m.comp", &warnings);
    ASSERT_TRUE(c.has_value());
    EXPECT_NE(warnings.find("m.comp:2: warning: unknown option 'frobnicate' ignored"), std::string::npos);
    EXPECT_NE(warnings.find("warning: no 'license' declaration"), std::string::npos);
}
