// SPDX-License-Identifier: GPL-2.0-or-later
// encoder_ratio(9) gear (kernel/components/encoder_ratio_core.h).
#include <gtest/gtest.h>

#include "encoder_ratio_core.h"

namespace {

// Quadrature levels of count n: 00, A, AB, B.
bool qa(int n) { return ((n & 3) == 1) || ((n & 3) == 2); }
bool qb(int n) { return (n & 3) >= 2; }

struct Gear {
    enc_ratio_state st{};
    enc_ratio_counts c{};
    int master = 0, slave = 0;
    void sample(bool enable) { enc_ratio_sample(&st, &c, qa(master), qb(master), qa(slave), qb(slave), enable); }
    void move(int dm, int ds, bool enable)
    {
        for (; dm || ds;) {
            if (dm) { master += dm > 0 ? 1 : -1; dm -= dm > 0 ? 1 : -1; }
            if (ds) { slave += ds > 0 ? 1 : -1; ds -= ds > 0 ? 1 : -1; }
            sample(enable);
        }
    }
};

TEST(EncoderRatio, DisabledErrorIsTheSlavePositionInRevolutions)
{
    Gear g;
    g.sample(false);
    g.move(400, 100, false);
    EXPECT_DOUBLE_EQ(enc_ratio_error(&g.c, 100, 100, 1, 1), 0.25);
}

TEST(EncoderRatio, EnabledErrorSubtractsTheScaledMasterMovement)
{
    Gear g;
    g.sample(false);
    g.move(0, 200, false);  // slave at 0.5 rev before enabling
    g.sample(true);
    g.move(-400, 0, true);  // master one revolution back, 2:1 teeth
    EXPECT_DOUBLE_EQ(enc_ratio_error(&g.c, 100, 100, 2, 1), 0.5 + 2.0);
    EXPECT_DOUBLE_EQ(enc_ratio_error(&g.c, 100, 100, 1, 4), 0.5 + 0.25);
    EXPECT_DOUBLE_EQ(enc_ratio_error(&g.c, 200, 50, 1, 1), 1.0 + 0.5);
}

TEST(EncoderRatio, MasterRestartsFromZeroWhenEnabledAgain)
{
    Gear g;
    g.sample(true);
    g.move(400, 0, true);
    g.sample(false);
    g.sample(true);
    EXPECT_DOUBLE_EQ(enc_ratio_error(&g.c, 100, 100, 1, 1), 0.0);
}

TEST(EncoderRatio, ZeroPprOrTeethDoNotDivideByZero)
{
    Gear g;
    g.sample(true);
    g.move(4, 4, true);
    EXPECT_DOUBLE_EQ(enc_ratio_error(&g.c, 0, 0, 1, 0), 1.0);
    EXPECT_DOUBLE_EQ(enc_ratio_error(&g.c, 0, 0, 1, 1), 0.0);
}

}  // namespace
