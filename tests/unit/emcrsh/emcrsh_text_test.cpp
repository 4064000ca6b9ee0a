// SPDX-License-Identifier: GPL-2.0-or-later
// emcrsh: command line, line reader, words, units.
#include <gtest/gtest.h>

#include <cmath>

#include "options.hpp"
#include "text.hpp"
#include "units.hpp"

using namespace hal::emcrsh;

static std::vector<std::string> lines(LineReader& r, int* too_long_count = nullptr)
{
    std::vector<std::string> out;
    for (;;) {
        bool tl = false;
        auto l = r.next(&tl);
        if (tl) {
            if (too_long_count)
                ++*too_long_count;
            out.push_back("<too long>");
            continue;
        }
        if (!l)
            return out;
        out.push_back(*l);
    }
}

TEST(EmcrshLineReader, AnyRunOfCrAndLfEndsALine)
{
    LineReader r;
    std::string in = "hello a b c\r\nget echo\n\rset x\r\r\n\nquit\n";
    r.append(in.data(), in.size());
    EXPECT_EQ(lines(r), (std::vector<std::string>{"hello a b c", "get echo", "set x", "quit"}));
}

TEST(EmcrshLineReader, KeepsAPartialLineUntilItsEnd)
{
    LineReader r;
    r.append("get ec", 6);
    EXPECT_TRUE(lines(r).empty());
    r.append("ho\r", 3);
    EXPECT_EQ(lines(r), std::vector<std::string>{"get echo"});
}

TEST(EmcrshLineReader, OverLongLineIsDroppedOnceAndTheNextOneKept)
{
    LineReader r;
    std::string big(MAX_LINE * 3, 'x');
    r.append(big.data(), big.size());
    EXPECT_LE(r.pending(), MAX_LINE);   // never grows past the cap
    std::string rest = "yyy\nget plat\n";
    r.append(rest.data(), rest.size());
    EXPECT_EQ(lines(r), (std::vector<std::string>{"<too long>", "get plat"}));
    std::string exact(MAX_LINE, 'z');
    exact += "\n";
    r.append(exact.data(), exact.size());
    EXPECT_EQ(lines(r), std::vector<std::string>{std::string(MAX_LINE, 'z')});
}

TEST(EmcrshLineReader, NulBytesAndBlankLines)
{
    LineReader r;
    std::string in("a\0b\n   \n\t\n", 10);
    r.append(in.data(), in.size());
    EXPECT_EQ(lines(r), std::vector<std::string>{"a b"});
}

TEST(EmcrshText, WordsAndRest)
{
    EXPECT_EQ(split_words("  set\tmdi  g0 x1 "), (std::vector<std::string>{"set", "mdi", "g0", "x1"}));
    EXPECT_EQ(rest_after("set mdi  g0  x1 ", 2), "g0  x1");
    EXPECT_EQ(rest_after("set open", 2), "");
    EXPECT_EQ(upper("Set_Wait"), "SET_WAIT");
    EXPECT_EQ(get_nak("MODE"), "GET MODE NAK\r\n\r\n");
    EXPECT_EQ(set_nak("MODE"), "SET MODE NAK\n\r");
    EXPECT_EQ(set_ack("MODE"), "SET MODE ACK\n\r");
    EXPECT_EQ(fmt(1), "1.000000");
}

TEST(EmcrshOptions, LauncherCommandLine)
{
    const char* argv[] = {"emcrsh", "-p", "0", "-n", "MILL", "-s", "2", "--", "-ini", "/x/mill.ini"};
    auto o = parse_options(10, argv);
    ASSERT_TRUE(o) << o.error().message;
    EXPECT_EQ(o->port, 0);
    EXPECT_EQ(o->name, "MILL");
    EXPECT_EQ(o->max_sessions, 2);
    EXPECT_EQ(o->ini, "/x/mill.ini");
    EXPECT_EQ(o->connect_pw, "EMC");
    EXPECT_EQ(o->enable_pw, "EMCTOO");
}

TEST(EmcrshOptions, LongNamesAndDefaults)
{
    const char* argv[] = {"linuxcncrsh", "--port", "6000", "--connectpw", "a", "--enablepw", "b", "--path", "/p"};
    auto o = parse_options(9, argv);
    ASSERT_TRUE(o);
    EXPECT_EQ(o->port, 6000);
    EXPECT_EQ(o->connect_pw, "a");
    EXPECT_EQ(o->enable_pw, "b");
    EXPECT_EQ(o->path, "/p");
    EXPECT_EQ(o->max_sessions, -1);
    EXPECT_EQ(o->name, "EMCNETSVR");
}

TEST(EmcrshOptions, BadValuesNameTheOption)
{
    const char* a1[] = {"emcrsh", "-p", "70000"};
    auto o = parse_options(3, a1);
    ASSERT_FALSE(o);
    EXPECT_NE(o.error().message.find("-p"), std::string::npos);
    const char* a2[] = {"emcrsh", "-s", "0"};
    EXPECT_FALSE(parse_options(3, a2));
    const char* a3[] = {"emcrsh", "--", "-display", "x"};
    EXPECT_FALSE(parse_options(4, a3));
    const char* a4[] = {"emcrsh", "-x"};
    EXPECT_FALSE(parse_options(2, a4));
    const char* a5[] = {"emcrsh", "-p"};
    EXPECT_FALSE(parse_options(2, a5));
}

TEST(EmcrshUnits, NamesByCloseness)
{
    EXPECT_EQ(linear_units_name(1.0), "MM");
    EXPECT_EQ(linear_units_name(0.03937), "INCH");
    EXPECT_EQ(linear_units_name(0.1), "CM");
    EXPECT_EQ(linear_units_name(0.5), "CUSTOM");
    EXPECT_EQ(angular_units_name("degree"), "DEG");
    EXPECT_EQ(angular_units_name(""), "DEG");
    EXPECT_EQ(angular_units_name("rad"), "RAD");
    EXPECT_EQ(angular_units_name("grad"), "GRAD");
    EXPECT_EQ(angular_units_name("0.01745329"), "RAD");
    EXPECT_EQ(angular_units_name("3"), "CUSTOM");
}

TEST(EmcrshUnits, Conversions)
{
    EXPECT_DOUBLE_EQ(convert_linear(25.4, 1.0, "INCH", "MM"), 1.0);
    EXPECT_DOUBLE_EQ(convert_linear(25.4, 1.0, "AUTO", "INCH"), 1.0);
    EXPECT_DOUBLE_EQ(convert_linear(25.4, 1.0, "AUTO", "MM"), 25.4);
    EXPECT_DOUBLE_EQ(convert_linear(20, 1.0, "CM", "MM"), 2.0);
    EXPECT_DOUBLE_EQ(convert_linear(1, 1.0 / 25.4, "MM", "MM"), 25.4);
    EXPECT_DOUBLE_EQ(convert_linear(7, 1.0, "CUSTOM", "MM"), 7.0);
    EXPECT_NEAR(convert_angular(180, "degree", "RAD"), M_PI, 1e-12);
    EXPECT_NEAR(convert_angular(90, "deg", "GRAD"), 100, 1e-12);
    EXPECT_DOUBLE_EQ(convert_angular(90, "deg", "AUTO"), 90);
}
