// SPDX-License-Identifier: GPL-2.0-or-later
// parport_cfg_test - the hal_parport cfg= grammar (small-boards.md §3.3).
#include <gtest/gtest.h>

#include <string>

#include "rtapi.h"
#include "parport_cfg.h"

namespace {

struct Parsed {
    int n;
    parport_cfg_entry e[PARPORT_MAX_PORTS];
    std::string why;
};

Parsed parse(const char* s)
{
    Parsed p{};
    char why[96] = "";
    p.n = parport_cfg_parse(s, p.e, why, sizeof(why));
    p.why = why;
    return p;
}

TEST(ParportCfg, AddressesAreHexWithOptionalPrefixAndTypesDefaultToOut)
{
    Parsed p = parse("0x378 278_0x3BC");
    ASSERT_EQ(p.n, 3);
    EXPECT_EQ(p.e[0].addr, 0x378u);
    EXPECT_EQ(p.e[1].addr, 0x278u);
    EXPECT_EQ(p.e[2].addr, 0x3bcu);
    EXPECT_EQ(p.e[0].type, PARPORT_OUT);
    EXPECT_EQ(p.e[2].type, PARPORT_OUT);
}

TEST(ParportCfg, TheFirstLetterOfATypeWordDecides)
{
    Parsed p = parse("0 in 0x278 output 0x3bc epp 0xd000 x 1 Input");
    ASSERT_EQ(p.n, 5);
    EXPECT_EQ(p.e[0].addr, 0u);
    EXPECT_EQ(p.e[0].type, PARPORT_IN);
    EXPECT_EQ(p.e[1].type, PARPORT_OUT);
    EXPECT_EQ(p.e[2].type, PARPORT_EPP);
    EXPECT_EQ(p.e[3].type, PARPORT_X);
    EXPECT_EQ(p.e[4].type, PARPORT_IN);
}

TEST(ParportCfg, BadAddressesAreRefusedNamingTheToken)
{
    Parsed p = parse("0x378 0x3z8");
    EXPECT_EQ(p.n, -EINVAL);
    EXPECT_EQ(p.why, "'0x3z8' is not a port address (hex, at most 0xffff) or parport number");
    EXPECT_EQ(parse("0x10000").n, -EINVAL);
    EXPECT_EQ(parse("0x").n, -EINVAL);
}

TEST(ParportCfg, AtMostEightPortsAndAtLeastOne)
{
    EXPECT_EQ(parse("1 2 3 4 5 6 7 8").n, 8);
    Parsed p = parse("1 2 3 4 5 6 7 8 9");
    EXPECT_EQ(p.n, -EINVAL);
    EXPECT_EQ(p.why, "more than 8 ports at '9'");
    EXPECT_EQ(parse(" _ ").n, -EINVAL);
}

}  // namespace
