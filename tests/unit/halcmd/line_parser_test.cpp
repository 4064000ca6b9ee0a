// SPDX-License-Identifier: GPL-2.0-or-later
// line_parser_test.cpp - words, quotes, comments, continuation lines, environment
// and inifile substitution (halcmd(1) SUBSTITUTION), and their errors.
#include <gtest/gtest.h>

#include <map>

#include "line_parser.hpp"

using namespace hal::halcmd;
using V = std::vector<std::string>;

namespace {

Substitutions env_of(std::map<std::string, std::string> vars, const IniFile* ini = nullptr)
{
    Substitutions s;
    s.env = [vars](const std::string& name) -> std::optional<std::string> {
        auto it = vars.find(name);
        if (it == vars.end())
            return std::nullopt;
        return it->second;
    };
    s.ini = ini;
    return s;
}

V words(std::string_view line, const Substitutions& s = env_of({}))
{
    auto r = tokenize(line, s);
    EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().message);
    return r ? *r : V{};
}

std::string error_of(std::string_view line, const Substitutions& s = env_of({}))
{
    auto r = tokenize(line, s);
    EXPECT_FALSE(r.has_value());
    return r ? "" : r.error().message;
}

}  // namespace

TEST(Tokenize, SplitsAtWhitespace)
{
    EXPECT_EQ(words("  net  sig\tpin.a   pin.b \r"), (V{"net", "sig", "pin.a", "pin.b"}));
}

TEST(Tokenize, EmptyAndBlankLinesHaveNoWords)
{
    EXPECT_TRUE(words("").empty());
    EXPECT_TRUE(words("   \t").empty());
}

TEST(Tokenize, CommentOutsideQuotesEndsTheLine)
{
    EXPECT_EQ(words("setp a 1 # set a"), (V{"setp", "a", "1"}));
    EXPECT_EQ(words("setp a 1#x"), (V{"setp", "a", "1"}));
    EXPECT_TRUE(words("# only a comment").empty());
}

TEST(Tokenize, HashInsideQuotesIsKept)
{
    EXPECT_EQ(words("echo \"a # b\" 'c # d'"), (V{"echo", "a # b", "c # d"}));
}

TEST(Tokenize, QuotesJoinWithAdjacentText)
{
    EXPECT_EQ(words("loadrt m names=\"a b\",c"), (V{"loadrt", "m", "names=a b,c"}));
}

TEST(Tokenize, EmptyQuotesMakeAnEmptyWord)
{
    EXPECT_EQ(words("echo \"\" ''"), (V{"echo", "", ""}));
}

TEST(Tokenize, BackslashEscapesInDoubleQuotes)
{
    EXPECT_EQ(words(R"(echo "say \"hi\" \\ \$HOME")"), (V{"echo", "say \"hi\" \\ $HOME"}));
}

TEST(Tokenize, UnterminatedQuotesAreErrors)
{
    EXPECT_EQ(error_of("echo \"abc"), "unterminated double quote");
    EXPECT_EQ(error_of("echo 'abc"), "unterminated single quote");
}

TEST(Tokenize, EnvironmentVariableBareAndParenthesised)
{
    auto s = env_of({{"N", "3"}, {"PREFIX", "and2.0"}});
    EXPECT_EQ(words("loadrt and2 count=$N", s), (V{"loadrt", "and2", "count=3"}));
    EXPECT_EQ(words("setp $(PREFIX).in0 1", s), (V{"setp", "and2.0.in0", "1"}));
}

TEST(Tokenize, BareVariableNameRunsToWhitespace)
{
    auto s = env_of({{"A.b", "x"}});
    EXPECT_EQ(words("echo $A.b", s), (V{"echo", "x"}));
}

TEST(Tokenize, UnquotedValueIsSplitQuotedIsNot)
{
    auto s = env_of({{"ARGS", "a b"}});
    EXPECT_EQ(words("echo $ARGS", s), (V{"echo", "a", "b"}));
    EXPECT_EQ(words("echo \"$ARGS\"", s), (V{"echo", "a b"}));
    EXPECT_EQ(words("echo '$ARGS'", s), (V{"echo", "$ARGS"}));
}

TEST(Tokenize, LoneDollarIsLiteral)
{
    EXPECT_EQ(words("echo $ cost$"), (V{"echo", "$", "cost$"}));
}

TEST(Tokenize, UnknownEnvironmentVariableIsNamed)
{
    EXPECT_EQ(error_of("echo $NOPE"), "environment variable 'NOPE' is not set");
    EXPECT_EQ(error_of("echo $(NOPE)x"), "environment variable 'NOPE' is not set");
}

TEST(Tokenize, BadParenthesisedVariable)
{
    EXPECT_EQ(error_of("echo $(ABC"), "missing ')' after '$('");
    EXPECT_EQ(error_of("echo $()"), "empty variable name in '$()'");
}

TEST(Tokenize, InifileVariables)
{
    IniFile ini = *IniFile::parse("[AXIS_0]\nSCALE = 2000\n# comment\n; other\n[EMCMOT]\nSERVO_PERIOD=1000000\n",
                                 "m.ini");
    auto s = env_of({}, &ini);
    EXPECT_EQ(words("setp stepgen.0.scale [AXIS_0]SCALE", s), (V{"setp", "stepgen.0.scale", "2000"}));
    EXPECT_EQ(words("echo x[EMCMOT](SERVO_PERIOD)y", s), (V{"echo", "x1000000y"}));
}

TEST(Tokenize, UnknownInifileVariableIsNamed)
{
    IniFile ini = *IniFile::parse("[A]\nB=1\n", "m.ini");
    auto s = env_of({}, &ini);
    EXPECT_EQ(error_of("echo [A]C", s), "inifile variable [A]C not found in 'm.ini'");
    EXPECT_EQ(error_of("echo [X](B)", s), "inifile variable [X]B not found in 'm.ini'");
}

TEST(Tokenize, BracketsWithoutInifileAreLiteral)
{
    EXPECT_EQ(words("echo [A]B"), (V{"echo", "[A]B"}));
}

TEST(Tokenize, BracketsNotOfTheFormAreLiteral)
{
    IniFile ini = *IniFile::parse("", "m.ini");
    auto s = env_of({}, &ini);
    EXPECT_EQ(words("echo [a b] [] [x]", s), (V{"echo", "[a", "b]", "[]", "[x]"}));
}

TEST(IniFile, FirstDefinitionWinsAndValuesAreTrimmed)
{
    IniFile ini = *IniFile::parse("[S]\n K =  v 1 \nK=v2\n", "x.ini");
    EXPECT_EQ(ini.find("S", "K"), "v 1");
    EXPECT_FALSE(ini.find("S", "X"));
    EXPECT_FALSE(ini.find("T", "K"));
}

TEST(IniFile, MissingFileIsAnError)
{
    auto r = IniFile::load("/nonexistent/dir/x.ini");
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("'/nonexistent/dir/x.ini'"), std::string::npos);
}

TEST(Continuation, TrailingBackslashJoinsLines)
{
    std::string logical;
    EXPECT_TRUE(join_continuation(logical, "net sig a \\\n"));
    EXPECT_TRUE(join_continuation(logical, "  b \\  "));
    EXPECT_FALSE(join_continuation(logical, "  c\n"));
    EXPECT_EQ(words(logical), (V{"net", "sig", "a", "b", "c"}));
}

TEST(Continuation, BackslashJoinsTheNextLineDirectly)
{
    std::string logical;
    EXPECT_TRUE(join_continuation(logical, "loadrt m names=d1\\\n"));
    EXPECT_FALSE(join_continuation(logical, ",d2\n"));
    EXPECT_EQ(logical, "loadrt m names=d1,d2");
    EXPECT_EQ(words(logical), (V{"loadrt", "m", "names=d1,d2"}));
}

TEST(Continuation, LineWithoutBackslashIsComplete)
{
    std::string logical;
    EXPECT_FALSE(join_continuation(logical, "show pin\r\n"));
    EXPECT_EQ(logical, "show pin");
}

TEST(Arrows, AllThreeAreRecognised)
{
    EXPECT_TRUE(is_arrow("=>"));
    EXPECT_TRUE(is_arrow("<="));
    EXPECT_TRUE(is_arrow("<=>"));
    EXPECT_FALSE(is_arrow("=="));
    EXPECT_FALSE(is_arrow("="));
}
