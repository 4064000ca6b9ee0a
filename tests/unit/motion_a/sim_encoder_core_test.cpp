// SPDX-License-Identifier: GPL-2.0-or-later
// sim_encoder(9) pulses (kernel/components/sim_encoder_core.h): quadrature order,
// index once per revolution, speed scaling, the one-count-per-period limit.
#include <gtest/gtest.h>

#include <string>

#include "sim_encoder_core.h"

namespace {

constexpr long kPeriodNs = 1000000;

struct Sim {
    sim_enc_shared sh{};
    sim_enc_state st{};
    sim_enc_out o{};
    // "A" "B" "Z" letters for the levels that are high, "-" for none.
    std::string step()
    {
        sim_enc_make_pulses(&st, &sh, kPeriodNs, &o);
        std::string s = std::string(o.a ? "A" : "") + (o.b ? "B" : "") + (o.z ? "Z" : "");
        return s.empty() ? "-" : s;
    }
};

TEST(SimEncoder, PositiveSpeedMakesALeadB)
{
    Sim s;
    sim_enc_update_speed(&s.sh, 2.5, 1.0, 100, kPeriodNs);  // 1000 counts/s: 1 per period
    std::string seq;
    for (int i = 0; i < 5; i++)
        seq += s.step() + " ";
    EXPECT_EQ(seq, "A AB B - A ");
}

TEST(SimEncoder, NegativeSpeedMakesBLeadA)
{
    Sim s;
    sim_enc_update_speed(&s.sh, -2.5, 1.0, 100, kPeriodNs);
    std::string seq;
    for (int i = 0; i < 4; i++)
        seq += s.step() + " ";
    EXPECT_EQ(seq, "B AB A - ");  // the index is at -400
}

TEST(SimEncoder, ScaleDividesSpeed)
{
    Sim s;
    sim_enc_update_speed(&s.sh, 150.0, 60.0, 100, kPeriodNs);  // 150 RPM = 2.5 rev/s
    EXPECT_EQ(rtapi_load_u64(&s.sh.addval), (rtapi_u64)SIM_ENC_ONE_COUNT);
    sim_enc_update_speed(&s.sh, 1.0, 0.0, 100, kPeriodNs);  // scale 0 is taken as 1
    EXPECT_EQ(rtapi_load_u64(&s.sh.addval), (rtapi_u64)(0.4 * SIM_ENC_ONE_COUNT + 0.5));
}

TEST(SimEncoder, FractionalSpeedStepsEveryFewPeriods)
{
    Sim s;
    sim_enc_update_speed(&s.sh, 0.625, 1.0, 100, kPeriodNs);  // 250 counts/s
    std::string seq;
    for (int i = 0; i < 8; i++)
        seq += s.step() + " ";
    EXPECT_EQ(seq, "Z Z Z A A A A AB ");
}

TEST(SimEncoder, IndexOncePerRevolution)
{
    Sim s;
    sim_enc_update_speed(&s.sh, 1000.0, 1.0, 3, kPeriodNs);  // capped at 1 count/period
    int rises = 0, first = -1;
    bool z = true;
    for (int i = 0; i < 36; i++) {
        s.step();
        if (s.o.z && !z) {
            rises++;
            if (first < 0)
                first = i;
        }
        z = s.o.z;
    }
    EXPECT_EQ(rises, 3);
    EXPECT_EQ(first, 11);  // count 12 = 4 * ppr
}

TEST(SimEncoder, SpeedIsLimitedToOneCountPerPeriod)
{
    Sim s;
    sim_enc_update_speed(&s.sh, 1e9, 1.0, 100, kPeriodNs);
    EXPECT_EQ(rtapi_load_u64(&s.sh.addval), (rtapi_u64)SIM_ENC_ONE_COUNT);
    sim_enc_update_speed(&s.sh, -1e9, 1.0, 100, kPeriodNs);
    EXPECT_EQ((rtapi_s64)rtapi_load_u64(&s.sh.addval), -SIM_ENC_ONE_COUNT);
}

TEST(SimEncoder, UsesThePeriodOfMakePulses)
{
    Sim s;
    s.step();  // make-pulses runs every 1 ms, update-speed every 10 ms
    sim_enc_update_speed(&s.sh, 1.25, 1.0, 100, 10 * kPeriodNs);
    EXPECT_EQ(rtapi_load_u64(&s.sh.addval), (rtapi_u64)SIM_ENC_ONE_COUNT / 2);
}

}  // namespace
