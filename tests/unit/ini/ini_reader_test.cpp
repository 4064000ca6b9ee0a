// SPDX-License-Identifier: GPL-2.0-or-later
// ini::Reader (task's and halui's configuration): the first error wins and later
// reads keep their defaults; [TRAJ]COORDINATES letters.
#include <gtest/gtest.h>

#include "ini/ini_reader.hpp"
#include "ini_of.hpp"

using hal::ini::IniFile;
using hal::ini::Reader;

namespace {

std::string coords_of(std::string_view text, std::string* err = nullptr)
{
    IniFile ini = ini_of(text);
    Reader r{ini, {}};
    std::string c = "XYZ";
    r.coordinates(c);
    if (err)
        *err = r.err;
    return c;
}

}  // namespace

TEST(IniReader, FirstErrorWins)
{
    IniFile ini = ini_of("[T]\nA = x\nB = 2\nC = inf\n");
    Reader r{ini, {}};
    double a = 1, b = 1, c = 1;
    r.d("T", "A", a);
    r.d("T", "B", b);
    r.d("T", "C", c);
    EXPECT_EQ(r.err.rfind("m.ini:2", 0), 0u) << r.err;
    EXPECT_DOUBLE_EQ(a, 1);
    EXPECT_DOUBLE_EQ(b, 1);   // skipped after the first error
}

TEST(IniReader, NonFiniteRefused)
{
    for (const char* v : {"inf", "1e999", "nan"}) {
        IniFile ini = ini_of(std::string("[T]\nC = ") + v + "\n");
        Reader r{ini, {}};
        double c = 1;
        r.d("T", "C", c);
        EXPECT_EQ(r.err.rfind("m.ini:2: [T]C: ", 0), 0u) << r.err;
        EXPECT_DOUBLE_EQ(c, 1) << v;
    }
}

TEST(IniReader, Coordinates)
{
    EXPECT_EQ(coords_of("[TRAJ]\n"), "XYZ");   // absent: the default stays
    EXPECT_EQ(coords_of("[TRAJ]\nCOORDINATES = x y z\n"), "XYZ");
    EXPECT_EQ(coords_of("[TRAJ]\nCOORDINATES = XYYZ\n"), "XYYZ");   // a gantry
    EXPECT_EQ(coords_of("[TRAJ]\nCOORDINATES = X Z C U V W A B\n"), "XZCUVWAB");
    std::string err;
    EXPECT_EQ(coords_of("[TRAJ]\nCOORDINATES = X Q\n", &err), "XYZ");
    EXPECT_EQ(err, "m.ini:2: [TRAJ]COORDINATES: 'Q' is not one of X Y Z A B C U V W");
}
