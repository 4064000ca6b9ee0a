// The simulated FPGA (hm2_sim_model.c): IDROM image, IOPort output stage, watchdog,
// encoder counting and stepgen accumulation, with time as an input.
#include <gtest/gtest.h>
#include <memory>

extern "C" {
#include "hm2_sim_model.h"
#include "hm2_idrom.h"
}

namespace {

std::unique_ptr<hm2_sim_model> make(const char *board, int fault = SIM_FAULT_NONE)
{
    auto m = std::make_unique<hm2_sim_model>();
    hm2_sim_model_init(m.get(), hm2_sim_layout_find(board), fault, 0);
    return m;
}

TEST(Hm2SimModel, IdromImagePassesTheDriverChecks)
{
    for (const char *board : {"5i25", "5i20", "5i23"}) {
        auto m = make(board);
        const sim_layout *l = hm2_sim_layout_find(board);
        char err[200] = "";
        rtapi_u32 cookie[3] = {hm2_sim_model_read(m.get(), 0x100), hm2_sim_model_read(m.get(), 0x104),
                               hm2_sim_model_read(m.get(), 0x108)};
        ASSERT_EQ(hm2_idrom_check_cookie(cookie, err, sizeof err), 0) << err;
        rtapi_u32 off = hm2_idrom_offset(hm2_sim_model_read(m.get(), 0x10C));
        rtapi_u32 w[HM2_IDROM_WORDS];
        for (int i = 0; i < HM2_IDROM_WORDS; i++)
            w[i] = hm2_sim_model_read(m.get(), off + 4 * i);
        hm2_board_shape shape{l->ports, l->port_width};
        hm2_idrom id{};
        ASSERT_EQ(hm2_idrom_parse(w, &shape, &id, err, sizeof err), 0) << err;
        for (int i = 0;; i++) {
            rtapi_u32 mw[3];
            for (int j = 0; j < 3; j++)
                mw[j] = hm2_sim_model_read(m.get(), off + id.offset_to_modules + 12 * i + 4 * j);
            hm2_md md{};
            int rc = hm2_md_parse(mw, &id, &md, err, sizeof err);
            ASSERT_GE(rc, 0) << err;
            if (rc == 1)
                break;
            EXPECT_EQ(hm2_md_is_consistent(&md, err, sizeof err), 0) << board << ": " << err;
        }
        for (rtapi_u32 i = 0; i < id.io_width; i++) {
            hm2_pd pd{};
            EXPECT_EQ(hm2_pd_parse(hm2_sim_model_read(m.get(), off + id.offset_to_pin_desc + 4 * i),
                                   i, &pd, err, sizeof err), 0) << err;
        }
    }
}

TEST(Hm2SimModel, FaultsChangeTheImage)
{
    EXPECT_EQ(hm2_sim_model_read(make("5i25", SIM_FAULT_NO_COOKIE).get(), 0x100), 0u);
    EXPECT_EQ(hm2_sim_model_read(make("5i25", SIM_FAULT_IDROM_OFFSET_0).get(), 0x10C), 0u);
    EXPECT_EQ(hm2_sim_model_read(make("5i25", SIM_FAULT_CLOCK_HIGH).get(), 0x400 + 44), 0u);
    EXPECT_EQ(hm2_sim_fault_find("port-width"), SIM_FAULT_PORT_WIDTH);
    EXPECT_EQ(hm2_sim_fault_find("nonsense"), -1);
    EXPECT_EQ(hm2_sim_layout_find("7i92"), nullptr);
}

TEST(Hm2SimModel, IoportOutputStage)
{
    auto m = make("5i25");
    hm2_sim_model *p = m.get();
    p->ext_in[16] = 1;	// pin 16 (port 0 bit 16) pulled high from outside
    hm2_sim_model_advance(p, 0);
    EXPECT_EQ((hm2_sim_model_read(p, 0x1000) >> 16) & 1, 1u);	// input reads the outside
    hm2_sim_model_write(p, 0x1000, 0);			// latch 0
    hm2_sim_model_write(p, 0x1100, 1u << 16);		// drive it
    EXPECT_EQ(p->level[16], 0);
    hm2_sim_model_write(p, 0x1400, 1u << 16);		// inverted
    EXPECT_EQ(p->level[16], 1);
    hm2_sim_model_write(p, 0x1400, 0);
    hm2_sim_model_write(p, 0x1000, 1u << 16);
    hm2_sim_model_write(p, 0x1300, 1u << 16);		// open drain, data 1: floats
    p->ext_in[16] = 0;
    hm2_sim_model_advance(p, 0);
    EXPECT_EQ(p->level[16], 0);
    p->ext_in[16] = 1;
    hm2_sim_model_advance(p, 0);
    EXPECT_EQ(p->level[16], 1);
    hm2_sim_model_write(p, 0x1000, 0);			// open drain, data 0: pulls low
    EXPECT_EQ(p->level[16], 0);
}

TEST(Hm2SimModel, WatchdogBitesAndReleasesPins)
{
    auto m = make("5i25");
    hm2_sim_model *p = m.get();
    hm2_sim_model_write(p, 0x1100, 0x1FFFF);
    hm2_sim_model_write(p, 0x0C00, 33333 - 1);		// 1 ms at 33.333 MHz
    hm2_sim_model_advance(p, 900000);			// 0.9 ms
    EXPECT_EQ(hm2_sim_model_read(p, 0x0D00), 0u);
    hm2_sim_model_write(p, 0x0E00, 0x5A000000);		// pet: reload
    hm2_sim_model_advance(p, 1800000);			// 0.9 ms after the pet
    EXPECT_EQ(hm2_sim_model_read(p, 0x0D00), 0u);
    hm2_sim_model_advance(p, 2000000);			// 1.1 ms after it
    EXPECT_EQ(hm2_sim_model_read(p, 0x0D00), 1u);
    EXPECT_EQ(hm2_sim_model_read(p, 0x1100), 0u);	// DDR cleared
    hm2_sim_model_write(p, 0x0D00, 0);
    EXPECT_EQ(hm2_sim_model_read(p, 0x0D00), 0u);
    hm2_sim_model_write(p, 0x0C00, 0x80000000u);	// disabled: never bites
    hm2_sim_model_advance(p, 900000000);
    EXPECT_EQ(hm2_sim_model_read(p, 0x0D00), 0u);
}

TEST(Hm2SimModel, EncoderCountsQuadratureAndLatchesIndex)
{
    auto m = make("5i25");
    hm2_sim_model *p = m.get();
    // encoder 0: A = pin 13, B = pin 14, index = pin 15; A leads B = up
    const int seq[4][2] = {{1, 0}, {1, 1}, {0, 1}, {0, 0}};
    long long t = 0;
    for (int k = 0; k < 10; k++) {
        p->ext_in[13] = seq[k % 4][0];
        p->ext_in[14] = seq[k % 4][1];
        hm2_sim_model_advance(p, t += 1000);
    }
    EXPECT_EQ(hm2_sim_model_read(p, 0x3000) & 0xFFFF, 10u);
    for (int k = 9; k >= 0; k--) {	// back down
        p->ext_in[13] = seq[(k + 3) % 4][0];
        p->ext_in[14] = seq[(k + 3) % 4][1];
        hm2_sim_model_advance(p, t += 1000);
    }
    EXPECT_EQ(hm2_sim_model_read(p, 0x3000) & 0xFFFF, 0u);
    // both inputs at once: quadrature error flag (bit 15)
    p->ext_in[13] = 1;
    p->ext_in[14] = 1;
    hm2_sim_model_advance(p, t += 1000);
    EXPECT_EQ(hm2_sim_model_read(p, 0x3100) & 0x8000u, 0x8000u);
    hm2_sim_model_write(p, 0x3100, 0);		// writing bit 15 = 0 clears it
    EXPECT_EQ(hm2_sim_model_read(p, 0x3100) & 0x8000u, 0u);
    // index latch, rising edge (polarity bit 3), once (bit 6)
    hm2_sim_model_write(p, 0x3100, (1u << 4) | (1u << 6) | (1u << 3));
    p->ext_in[13] = 0;				// one more count: 1,1 -> 0,1 is up
    hm2_sim_model_advance(p, t += 1000);
    p->ext_in[15] = 1;
    hm2_sim_model_advance(p, t += 1000);
    rtapi_u32 ctl = hm2_sim_model_read(p, 0x3100);
    EXPECT_EQ(ctl & (1u << 4), 0u);			// latch bit cleared: event happened
    EXPECT_EQ(ctl >> 16, hm2_sim_model_read(p, 0x3000) & 0xFFFF);
    EXPECT_EQ(ctl & 4u, 4u);				// index input level
    hm2_sim_model_write(p, 0x3000, 0);		// any write clears the count
    EXPECT_EQ(hm2_sim_model_read(p, 0x3000) & 0xFFFF, 0u);
}

TEST(Hm2SimModel, StepgenAccumulatesTheRate)
{
    auto m = make("5i25");
    hm2_sim_model *p = m.get();
    // 1000 steps/s: rate = 1000 * 2^32 / 33333333
    rtapi_u32 rate = static_cast<rtapi_u32>(1000.0 * 4294967296.0 / 33333333.0);
    hm2_sim_model_write(p, 0x2000, rate);
    hm2_sim_model_advance(p, 100000000);		// 0.1 s: 100 steps
    double steps = static_cast<rtapi_s32>(hm2_sim_model_read(p, 0x2100)) / 65536.0;
    EXPECT_NEAR(steps, 100.0, 0.01);
    hm2_sim_model_write(p, 0x2000, static_cast<rtapi_u32>(-static_cast<rtapi_s32>(rate)));
    hm2_sim_model_advance(p, 300000000);		// 0.2 s back: -100
    steps = static_cast<rtapi_s32>(hm2_sim_model_read(p, 0x2100)) / 65536.0;
    EXPECT_NEAR(steps, -100.0, 0.01);
    hm2_sim_model_write(p, 0x4000, 0x12345678);	// plain register reads back
    EXPECT_EQ(hm2_sim_model_read(p, 0x4000), 0x12345678u);
}

// 5i23: muxed encoders 2 and 3 share pins 27-29; each counts its own channel (the
// outside multiplexer's inputs), the data pins show the selected one.
TEST(Hm2SimModel, MuxedEncodersCountTheirOwnChannel)
{
    auto m = make("5i23");
    hm2_sim_model *p = m.get();
    const int seq[4][2] = {{1, 0}, {1, 1}, {0, 1}, {0, 0}};
    long long t = 0;
    for (int k = 0; k < 6; k++) {
        p->mux_in[3][0] = seq[k % 4][0];
        p->mux_in[3][1] = seq[k % 4][1];
        hm2_sim_model_advance(p, t += 1000);
    }
    for (int k = 2; k >= 1; k--) {	// encoder 2 goes down: 00 -> 01 -> 11
        p->mux_in[2][0] = seq[k][0];
        p->mux_in[2][1] = seq[k][1];
        hm2_sim_model_advance(p, t += 1000);
    }
    EXPECT_EQ(hm2_sim_model_read(p, 0x350C) & 0xFFFF, 6u);
    EXPECT_EQ(hm2_sim_model_read(p, 0x3508) & 0xFFFF, 0xFFFEu);	// -2
    EXPECT_EQ(hm2_sim_model_read(p, 0x3500) & 0xFFFF, 0u);
    // the data pin of unit 1 carries the selected channel's A
    int sel = p->mux_sel;
    EXPECT_EQ(p->ext_in[27], p->mux_in[2 + sel][0]);
}

// 3pwmgen: an active fault input latches fault and clears enable; enabling clears it.
TEST(Hm2SimModel, TppwmFaultLatches)
{
    auto m = make("5i23");
    hm2_sim_model *p = m.get();
    long long t = 0;
    p->ext_in[55] = 1;			// fault input high: no fault (active low)
    hm2_sim_model_write(p, 0x4600, 1);
    hm2_sim_model_advance(p, t += 1000);
    EXPECT_EQ(hm2_sim_model_read(p, 0x4600), 1u);
    p->ext_in[55] = 0;
    hm2_sim_model_advance(p, t += 1000);
    EXPECT_EQ(hm2_sim_model_read(p, 0x4600), 2u);
    p->ext_in[55] = 1;
    hm2_sim_model_advance(p, t += 1000);
    EXPECT_EQ(hm2_sim_model_read(p, 0x4600), 2u);	// latched
    hm2_sim_model_write(p, 0x4600, 1);
    EXPECT_EQ(hm2_sim_model_read(p, 0x4600), 1u);
}

// BSPI with the 7i65: descriptors #15..#0, frames timed by the bit rate, replies in
// order, no-echo frames give none; the DAC -> ADC loop; the CPLD; the card watchdog.
TEST(Hm2SimModel, BspiFramesReachThe7i65)
{
    auto m = make("5i23");
    hm2_sim_model *p = m.get();
    rtapi_u32 cd[16] = {};
    cd[0] = 31u | (0x10u << 24);				// CS0 loop-back, 32 bits
    cd[1] = 23u | (1u << 16) | (0x10u << 24) | (1u << 31);	// CS1 DAC, no echo
    cd[3] = 15u | (3u << 8) | (3u << 16) | (0x10u << 24);	// CS3 ADC, 16 bits, N = 3
    cd[4] = 11u | (4u << 16) | (0x10u << 24);		// CS4 CPLD
    for (int j = 15; j >= 0; j--)
        hm2_sim_model_write(p, 0x5500, cd[j]);
    EXPECT_EQ(hm2_sim_model_read(p, 0x5504), cd[1]);
    long long t = 0;
    hm2_sim_model_write(p, 0x5400, 0xDEADBEEF);		// loop-back
    hm2_sim_model_write(p, 0x5404, (2u << 16) | 16383u);	// DAC channel 2 = +5 V
    hm2_sim_model_write(p, 0x540C, 0x8000u | (2u << 10));	// ADC: next = channel 2
    hm2_sim_model_write(p, 0x540C, 0x8000u);		// reply: channel 2
    p->card.din[1] = 1;
    hm2_sim_model_write(p, 0x5410, 0xA05);			// enables 0 and 2
    EXPECT_EQ(hm2_sim_model_read(p, 0x5600), 5u << 8);	// 5 frames waiting
    hm2_sim_model_advance(p, t += 100);			// 4.8 ticks: nothing done yet
    EXPECT_EQ(hm2_sim_model_read(p, 0x5600) & 0x1F, 0u);
    hm2_sim_model_advance(p, t += 1000000);
    EXPECT_EQ(hm2_sim_model_read(p, 0x5600), 4u);		// 4 replies, TX empty
    EXPECT_EQ(hm2_sim_model_read(p, 0x5400), 0xDEADBEEFu);
    EXPECT_EQ(hm2_sim_model_read(p, 0x5400) >> 13, 0u);	// ADC reply for channel 0
    EXPECT_EQ(hm2_sim_model_read(p, 0x5400), (2u << 13) | (16383u / 8));
    EXPECT_EQ(hm2_sim_model_read(p, 0x5400), 2u);		// CPLD: input 1
    EXPECT_EQ(p->card.dac[2], 16383);
    EXPECT_EQ(p->card.enables, 5u);
    hm2_sim_model_advance(p, t += 60000000);		// 60 ms without the CPLD
    EXPECT_EQ(p->card.bitten, 1);
    EXPECT_EQ(p->card.dac[2], 0);
    EXPECT_EQ(p->card.enables, 0u);
    hm2_sim_model_write(p, 0x5600, 0);			// any write empties the FIFOs
    EXPECT_EQ(hm2_sim_model_read(p, 0x5600), 0u);
}

// UART with a loop-back plug: bytes at the bit rate, 1..4 per word, lost when the
// RX rate differs.
TEST(Hm2SimModel, UartLoopsBack)
{
    auto m = make("5i23");
    hm2_sim_model *p = m.get();
    rtapi_u32 rate = (rtapi_u32)((115200ull << 20) / 48000000u);
    hm2_sim_model_write(p, 0x6200, rate);
    hm2_sim_model_write(p, 0x6600, rate);
    long long t = 0;
    hm2_sim_model_write(p, 0x600C, 0x44434241u);		// 4 bytes "ABCD"
    hm2_sim_model_write(p, 0x6000, 0x45u);			// 1 byte "E"
    EXPECT_EQ(hm2_sim_model_read(p, 0x6100), 5u);
    hm2_sim_model_advance(p, t += 50000);			// 50 us: not a whole byte yet
    EXPECT_EQ(hm2_sim_model_read(p, 0x6500), 0u);
    hm2_sim_model_advance(p, t += 1000000);
    EXPECT_EQ(hm2_sim_model_read(p, 0x6500), 5u);
    EXPECT_EQ(hm2_sim_model_read(p, 0x6700) & 0x80u, 0x80u);	// data waiting
    EXPECT_EQ(hm2_sim_model_read(p, 0x6404), 0x4241u);	// +4: two bytes
    EXPECT_EQ(hm2_sim_model_read(p, 0x640C), 0x454443u);	// +C: the three left
    EXPECT_EQ(hm2_sim_model_read(p, 0x6500), 0u);
    hm2_sim_model_write(p, 0x6600, rate + 1);
    hm2_sim_model_write(p, 0x6000, 0x46u);
    hm2_sim_model_advance(p, t += 1000000);
    EXPECT_EQ(hm2_sim_model_read(p, 0x6500), 0u);
    EXPECT_EQ(hm2_sim_model_read(p, 0x6700) & 1u, 1u);	// false start
}

}  // namespace
