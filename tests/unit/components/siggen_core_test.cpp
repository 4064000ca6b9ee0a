// SPDX-License-Identifier: GPL-2.0-or-later
// siggen(9) waveforms (kernel/components/siggen_core.h): the phase relations the
// page states, amplitude/offset, and the Nyquist clamp.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "siggen_core.h"

namespace {

constexpr long kPeriodNs = 1000000;  // 1 ms: 250 Hz gives quarter-cycle steps

siggen_out step(siggen_state& s, double freq, double amp = 1.0, double offset = 0.0)
{
    siggen_out o{};
    siggen_step(&s, freq, amp, offset, kPeriodNs, &o);
    return o;
}

TEST(Siggen, QuarterCycleStepsHitThePeaks)
{
    siggen_state s{};
    siggen_out o = step(s, 250.0);  // phase 0.25
    EXPECT_NEAR(o.sine, 1.0, 1e-12);
    EXPECT_NEAR(o.cosine, 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(o.triangle, 0.0);
    EXPECT_DOUBLE_EQ(o.sawtooth, -0.5);
    EXPECT_DOUBLE_EQ(o.square, -1.0);
    EXPECT_FALSE(o.clock);

    o = step(s, 250.0);  // phase 0.5
    EXPECT_NEAR(o.sine, 0.0, 1e-12);
    EXPECT_NEAR(o.cosine, -1.0, 1e-12);
    EXPECT_DOUBLE_EQ(o.triangle, -1.0);
    EXPECT_DOUBLE_EQ(o.sawtooth, 0.0);
    EXPECT_DOUBLE_EQ(o.square, 1.0);
    EXPECT_TRUE(o.clock);

    o = step(s, 250.0);  // phase 0.75
    EXPECT_NEAR(o.sine, -1.0, 1e-12);
    EXPECT_DOUBLE_EQ(o.triangle, 0.0);
    EXPECT_DOUBLE_EQ(o.sawtooth, 0.5);
    EXPECT_DOUBLE_EQ(o.square, 1.0);

    o = step(s, 250.0);  // phase wraps to 0
    EXPECT_NEAR(o.cosine, 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(o.triangle, 1.0);
    EXPECT_DOUBLE_EQ(o.sawtooth, -1.0);
    EXPECT_DOUBLE_EQ(o.square, -1.0);
    EXPECT_FALSE(o.clock);
}

// The page: square is positive while triangle and cosine ramp up and while sine
// is negative; the sawtooth drops when cosine peaks, with square's falling edge.
TEST(Siggen, PhaseRelationsHoldOverACycle)
{
    siggen_state s{};
    siggen_out prev = step(s, 10.0);
    for (int i = 0; i < 300; i++) {
        siggen_out o = step(s, 10.0);
        if (o.square > 0) {
            EXPECT_LE(o.sine, 1e-9);
            if (prev.square > 0) {
                EXPECT_GT(o.triangle, prev.triangle);
                EXPECT_GE(o.cosine, prev.cosine - 1e-12);
            }
        }
        if (o.sawtooth < prev.sawtooth) {  // the drop
            EXPECT_GT(prev.square, 0);
            EXPECT_LT(o.square, 0);
            EXPECT_GT(o.cosine, 0.99);
        }
        EXPECT_EQ(o.clock, o.square > 0);
        prev = o;
    }
}

TEST(Siggen, AmplitudeAndOffsetScaleEveryOutput)
{
    siggen_state s{};
    double lo = 1e9, hi = -1e9;
    for (int i = 0; i < 8; i++) {
        siggen_out o = step(s, 125.0, 2.5, 10.0);  // eighth-cycle steps
        for (double v : {o.sine, o.cosine, o.triangle, o.sawtooth, o.square}) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    EXPECT_NEAR(lo, 7.5, 1e-12);
    EXPECT_NEAR(hi, 12.5, 1e-12);
}

TEST(Siggen, SineLagsCosineByAQuarterCycle)
{
    siggen_state a{}, b{};
    step(b, 250.0);  // b runs a quarter cycle ahead of a
    for (int i = 0; i < 5; i++) {
        siggen_out oa = step(a, 250.0);
        siggen_out ob = step(b, 250.0);
        EXPECT_NEAR(ob.sine, oa.cosine, 1e-12);
    }
}

TEST(Siggen, FrequencyIsClampedToHalfTheSampleRate)
{
    siggen_state s{};
    step(s, 1e6);
    EXPECT_DOUBLE_EQ(s.phase, 0.5);
    step(s, -1e6);
    EXPECT_DOUBLE_EQ(s.phase, 0.0);
}

TEST(Siggen, NegativeFrequencyRunsBackwards)
{
    siggen_state s{};
    siggen_out o = step(s, -250.0);
    EXPECT_DOUBLE_EQ(s.phase, 0.75);
    EXPECT_DOUBLE_EQ(o.sawtooth, 0.5);
}

TEST(Siggen, NanFrequencyHoldsThePhase)
{
    siggen_state s{};
    step(s, 250.0);
    step(s, std::numeric_limits<double>::quiet_NaN());
    EXPECT_DOUBLE_EQ(s.phase, 0.25);
}

TEST(Siggen, ZeroFrequencyIsSteady)
{
    siggen_state s{};
    siggen_out o = step(s, 0.0);
    EXPECT_DOUBLE_EQ(s.phase, 0.0);
    EXPECT_DOUBLE_EQ(o.cosine, 1.0);
}

}  // namespace
