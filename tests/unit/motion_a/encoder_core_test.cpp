// SPDX-License-Identifier: GPL-2.0-or-later
// encoder(9) counting and estimating (kernel/components/encoder_core.h): the
// quadrature state machine in x4/x1/counter mode, index and latch handshakes,
// reset, missing teeth, and the edge-timed velocity estimate.
#include <gtest/gtest.h>

#include "encoder_core.h"

namespace {

constexpr long kPeriodNs = 1000000;  // 1 ms

bool qa(int n) { return ((n & 3) == 1) || ((n & 3) == 2); }
bool qb(int n) { return (n & 3) >= 2; }

struct Enc {
    enc_update_state up{};
    enc_shared sh{};
    enc_acks acks{};
    enc_capture_state cap{};
    enc_update_in in{};
    enc_capture_in cin{};
    enc_capture_out out{};
    int pos = 0;  // the simulated shaft, in quadrature counts

    Enc()
    {
        in.x4_mode = true;
        in.latch_rising = in.latch_falling = true;
        cin.scale = 1.0;
        cin.min_speed = 1.0;
    }
    rtapi_s32 update()
    {
        in.a = qa(pos);
        in.b = qb(pos);
        return enc_update(&up, &sh, &acks, &in, kPeriodNs);
    }
    const enc_capture_out& capture()
    {
        enc_shared snap;
        enc_shared_read(&sh, &snap);
        enc_capture(&cap, &snap, &acks, &cin, &out);
        if (out.clear_index_enable)
            cin.index_enable = in.index_enable = false;
        return out;
    }
    const enc_capture_out& period()
    {
        update();
        return capture();
    }
    void move(int counts)
    {
        for (; counts; counts += counts > 0 ? -1 : 1) {
            pos += counts > 0 ? 1 : -1;
            period();
        }
    }
};

TEST(EncoderQuad, X4CountsEveryEdgeBothWays)
{
    for (rtapi_u8 p = 0; p < 4; p++) {
        EXPECT_EQ(enc_quad_delta(p, (p + 1) & 3, true), 1);
        EXPECT_EQ(enc_quad_delta(p, (p + 3) & 3, true), -1);
        EXPECT_EQ(enc_quad_delta(p, p, true), 0);
        EXPECT_EQ(enc_quad_delta(p, (p + 2) & 3, true), 0);  // missed edge: no guess
    }
    EXPECT_EQ(enc_quad_pos(false, false), 0);
    EXPECT_EQ(enc_quad_pos(true, false), 1);  // A leads B going up
    EXPECT_EQ(enc_quad_pos(true, true), 2);
    EXPECT_EQ(enc_quad_pos(false, true), 3);
}

TEST(EncoderQuad, X4FollowsTheShaft)
{
    Enc e;
    e.period();
    e.move(10);
    EXPECT_EQ(e.out.counts, 10);
    e.move(-25);
    EXPECT_EQ(e.out.counts, -15);
    EXPECT_EQ(e.sh.raw, -15);
}

TEST(EncoderQuad, X1CountsOncePerCycleWithoutDrift)
{
    Enc e;
    e.in.x4_mode = false;
    e.period();
    e.move(8);
    EXPECT_EQ(e.out.counts, 2);
    e.move(-8);
    EXPECT_EQ(e.out.counts, 0);
    for (int i = 0; i < 5; i++) {  // chatter on the counting edge
        e.move(1);
        e.move(-1);
    }
    EXPECT_EQ(e.out.counts, 0);
}

TEST(EncoderCounter, CountsRisingEdgesOfAIgnoringB)
{
    Enc e;
    e.in.counter_mode = true;
    e.period();
    for (int i = 0; i < 3; i++) {
        e.in.b = !e.in.b;
        enc_update(&e.up, &e.sh, &e.acks, &e.in, kPeriodNs);
        e.in.a = true;
        enc_update(&e.up, &e.sh, &e.acks, &e.in, kPeriodNs);
        e.in.a = false;
        enc_update(&e.up, &e.sh, &e.acks, &e.in, kPeriodNs);
    }
    e.capture();
    EXPECT_EQ(e.out.counts, 3);
}

TEST(EncoderIndex, ResetsCountsOnZRisingAndClearsIndexEnable)
{
    Enc e;
    e.period();
    e.move(5);
    e.in.z = true;  // not armed: ignored
    e.period();
    e.in.z = false;
    e.period();
    EXPECT_EQ(e.out.counts, 5);
    e.in.index_enable = e.cin.index_enable = true;
    e.move(3);
    e.in.z = true;
    e.period();
    EXPECT_TRUE(e.out.clear_index_enable);
    EXPECT_FALSE(e.in.index_enable);
    EXPECT_EQ(e.out.counts, 0);
    e.move(2);
    EXPECT_EQ(e.out.counts, 2);
    EXPECT_EQ(e.sh.raw, 10);  // rawcounts is not affected
}

TEST(EncoderIndex, FirstPulseWinsUntilCaptureTakesIt)
{
    Enc e;
    e.period();
    e.in.index_enable = e.cin.index_enable = true;
    e.in.z = true;
    e.update();  // index at raw 0
    e.in.z = false;
    e.pos += 1;
    e.update();
    e.pos += 1;
    e.in.z = true;
    e.update();  // a second pulse at raw 2 before capture ran
    e.capture();
    EXPECT_EQ(e.out.counts, 2);
}

TEST(EncoderIndex, WithdrawnRequestIsIgnored)
{
    Enc e;
    e.period();
    e.move(4);
    e.in.index_enable = true;
    e.in.z = true;
    e.update();
    e.cin.index_enable = false;  // someone cleared index-enable meanwhile
    e.capture();
    EXPECT_FALSE(e.out.clear_index_enable);
    EXPECT_EQ(e.out.counts, 4);
}

TEST(EncoderReset, HoldsCountsAtZero)
{
    Enc e;
    e.period();
    e.move(7);
    e.cin.reset = true;
    e.period();
    EXPECT_EQ(e.out.counts, 0);
    e.move(3);
    EXPECT_EQ(e.out.counts, 0);
    e.cin.reset = false;
    e.move(2);
    EXPECT_EQ(e.out.counts, 2);
    EXPECT_DOUBLE_EQ(e.out.position, 2.0);
}

TEST(EncoderLatch, LatchesOnTheSelectedEdges)
{
    Enc e;
    e.cin.scale = 2.0;
    e.period();
    e.move(4);
    e.in.latch_input = true;  // rising
    e.period();
    EXPECT_EQ(e.out.counts_latched, 4);
    EXPECT_DOUBLE_EQ(e.out.position_latched, 2.0);
    e.move(2);
    e.in.latch_falling = false;
    e.in.latch_input = false;  // falling, not selected
    e.period();
    EXPECT_EQ(e.out.counts_latched, 4);
    e.in.latch_falling = true;
    e.in.latch_rising = false;
    e.in.latch_input = true;  // rising, not selected now
    e.period();
    e.move(1);
    e.in.latch_input = false;
    e.period();
    EXPECT_EQ(e.out.counts_latched, 7);
}

TEST(EncoderScale, PositionIsCountsOverScaleAndZeroScaleMeansOne)
{
    Enc e;
    e.cin.scale = 500.0;
    e.period();
    e.move(1000);
    EXPECT_DOUBLE_EQ(e.out.position, 2.0);
    e.cin.scale = 0.0;
    e.period();
    EXPECT_DOUBLE_EQ(e.out.position, 1000.0);
}

TEST(EncoderMissingTeeth, GapAddsTheMissingTeethAndIsAnIndex)
{
    Enc e;
    e.in.counter_mode = true;
    e.in.missing_teeth = 2;
    e.in.index_enable = e.cin.index_enable = true;
    auto tooth = [&e](int gap_periods) {
        for (int i = 0; i < gap_periods - 1; i++)
            e.period();
        e.in.a = true;
        enc_update(&e.up, &e.sh, &e.acks, &e.in, kPeriodNs);
        e.capture();
        e.in.a = false;
    };
    e.in.a = false;
    e.period();
    for (int i = 0; i < 5; i++)
        tooth(4);
    EXPECT_EQ(e.sh.raw, 5);
    EXPECT_TRUE(e.in.index_enable);
    tooth(12);  // 3 tooth intervals: two teeth missing
    EXPECT_EQ(e.sh.raw, 8);
    EXPECT_FALSE(e.in.index_enable);
    EXPECT_EQ(e.out.counts, 0);
    tooth(4);
    EXPECT_EQ(e.out.counts, 1);
}

TEST(EncoderVelocity, CountsBetweenEdgesOverTheTimeBetweenThem)
{
    Enc e;
    e.cin.min_speed = 0.0;
    e.period();
    for (int n = 0; n < 5; n++) {  // one count every 4 ms: 250 counts/s
        for (int i = 0; i < 3; i++)
            e.period();
        e.pos++;
        e.period();
    }
    EXPECT_DOUBLE_EQ(e.out.velocity, 250.0);
    e.period();  // between edges the estimate holds: no quantization noise
    EXPECT_DOUBLE_EQ(e.out.velocity, 250.0);
    EXPECT_DOUBLE_EQ(e.out.position_interpolated, e.out.position + 0.25);
    e.cin.scale = -10.0;
    e.period();
    EXPECT_DOUBLE_EQ(e.out.velocity, -25.0);
}

TEST(EncoderVelocity, DecaysWhenEdgesStopAndReadsZeroBelowMinSpeed)
{
    Enc e;
    e.period();
    for (int n = 0; n < 5; n++) {  // 500 counts/s
        e.period();
        e.pos++;
        e.period();
    }
    EXPECT_DOUBLE_EQ(e.out.velocity, 500.0);
    for (int i = 0; i < 10; i++)
        e.period();
    EXPECT_DOUBLE_EQ(e.out.velocity, 100.0);  // at most 1 count per 10 ms
    e.cin.min_speed = 200.0;
    e.period();
    EXPECT_DOUBLE_EQ(e.out.velocity, 0.0);
    EXPECT_DOUBLE_EQ(e.out.position_interpolated, e.out.position);
}

TEST(EncoderVelocity, NegativeWhenCountingDown)
{
    Enc e;
    e.period();
    for (int n = 0; n < 4; n++) {
        e.period();
        e.pos--;
        e.period();
    }
    EXPECT_DOUBLE_EQ(e.out.velocity, -500.0);
    EXPECT_DOUBLE_EQ(e.out.position_interpolated, e.out.position);  // 0 ms since the edge
    e.period();
    EXPECT_DOUBLE_EQ(e.out.position_interpolated, e.out.position - 0.5);
}

TEST(EncoderShared, ReadCopiesAConsistentSnapshot)
{
    Enc e;
    e.period();
    e.move(3);
    enc_shared snap{};
    enc_shared_read(&e.sh, &snap);
    EXPECT_EQ(snap.raw, 3);
    EXPECT_EQ(snap.now_ns, e.sh.now_ns);
    EXPECT_EQ(snap.edge_ns, e.sh.now_ns);
    EXPECT_EQ(snap.seq % 2, 0u);
}

}  // namespace
