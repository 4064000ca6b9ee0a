// SPDX-License-Identifier: GPL-2.0-or-later
// hm2_pci's PLX sequences (hm2_plx.c) against the PLX bridge model (sim/hm2_sim_plx.c)
// in front of the configuration-port model, reached through rtapi_pci's simulated
// cards and its driver interface (subsystem IDs, I/O BARs), as hm2_pci reaches them.
#include <gtest/gtest.h>
#include <vector>

extern "C" {
#include "rtapi.h"
#include "rtapi_pci.h"
#include "hm2_bitfile.h"
#include "hm2_plx.h"
#include "hm2_sim_plx.h"
}
#include "sim_bitstream.h"

namespace {

// A PLX card: BAR1 the bridge's registers, BAR2 the data port, BAR3 a plain window.
struct Card {
	hm2_sim_fpgacfg fpga{};
	hm2_sim_plx plx{};
	rtapi_u32 window = 0x12345678;
	int handle = -1;
};

rtapi_u32 cardRead(void *dev, int bar, unsigned long off, int size)
{
	Card *c = static_cast<Card *>(dev);
	if (bar == 3)
		return c->window;
	rtapi_u32 v = hm2_sim_plx_read(&c->plx, off & ~3ul);
	return size == 1 ? (v >> (8 * (off & 3))) & 0xff : v;
}

void cardWrite(void *dev, int bar, unsigned long off, int size, rtapi_u32 v)
{
	Card *c = static_cast<Card *>(dev);
	if (bar == 2 && size == 1)
		hm2_sim_plx_data(&c->plx, (rtapi_u8)v);
	else if (bar == 1 && size == 4)
		hm2_sim_plx_write(&c->plx, off, v);
}

const rtapi_pcisim_ops kOps = {nullptr, nullptr, cardRead, cardWrite};
const rtapi_pci_id kIds[] = {{0x10B5, 0x9030, 0x10B5, 0x3131}, {0x10B5, 0x9054, 0x10B5, 0x3315}, {0, 0, 0, 0}};

struct Found {
	int probes = 0, removes = 0, which = -1;
	rtapi_pci_bar *ctrl = nullptr, *data = nullptr, *window = nullptr;
};
Found found;

int probe(rtapi_pci_dev *dev, const rtapi_pci_id *id)
{
	found.probes++;
	found.which = (int)(id - kIds);
	rtapi_pci_set_drvdata(dev, &found);
	if (rtapi_pci_dev_map_bar(dev, 1, &found.ctrl) || rtapi_pci_dev_map_bar(dev, 2, &found.data) ||
	    rtapi_pci_dev_map_bar(dev, 3, &found.window))
		return -EIO;
	return 0;
}

void remove(rtapi_pci_dev *dev)
{
	Found *f = static_cast<Found *>(rtapi_pci_get_drvdata(dev));
	f->removes++;
	rtapi_pci_unmap_bar(f->ctrl);
	rtapi_pci_unmap_bar(f->data);
	rtapi_pci_unmap_bar(f->window);
}

rtapi_pci_driver driver = {"plx_test", kIds, probe, remove, nullptr};

class Plx : public ::testing::Test {
protected:
	// one simulated card with these IDs, bound by the driver
	void attach(sim_plx_type type, sim_plx_fault fault, unsigned subdevice)
	{
		hm2_sim_plx_init(&card.plx, type, fault, &card.fpga);
		rtapi_pcisim_card c{};
		c.id = {0x10B5, type == SIM_PLX_9030 ? 0x9030u : 0x9054u, 0x10B5, subdevice};
		c.bar_len[1] = c.bar_len[2] = 256;
		c.bar_len[3] = 0x10000;
		card.handle = rtapi_pcisim_register_card(&c, &kOps, &card, "plx-test");
		ASSERT_GE(card.handle, 0);
		found = Found();
		taken = rtapi_pci_register_driver(&driver);
	}
	void TearDown() override
	{
		if (taken > 0)
			rtapi_pci_unregister_driver(&driver);
		if (card.handle >= 0)
			rtapi_pcisim_unregister(card.handle);
		taken = 0;
		card.handle = -1;
	}
	int program9030(const std::vector<unsigned char> &s)
	{
		int rc = hm2_plx9030_reset(found.ctrl, "t");
		return rc ? rc : hm2_plx9030_program(found.ctrl, found.data, s.data(), (rtapi_u32)s.size(), "t");
	}
	int program9054(const std::vector<unsigned char> &s)
	{
		int rc = hm2_plx9054_reset(found.ctrl, "t");
		return rc ? rc : hm2_plx9054_program(found.ctrl, found.data, s.data(), (rtapi_u32)s.size(), "t");
	}
	Card card;
	int taken = 0;
};

TEST_F(Plx, DriverFindsTheCardBySubsystemIdAndMapsItsBars)
{
	attach(SIM_PLX_9054, SIM_PLX_OK, 0x3315);
	EXPECT_EQ(taken, 1);
	EXPECT_EQ(found.which, 1);
	EXPECT_EQ(rtapi_pci_readl(found.window, 0x100), 0x12345678u);
	EXPECT_EQ(rtapi_pci_readl(found.window, 0x10000), ~0u);	// outside the BAR
	rtapi_pci_unregister_driver(&driver);
	taken = 0;
	EXPECT_EQ(found.removes, 1);
}

TEST_F(Plx, ACardWithOtherSubsystemIdsIsNotTaken)
{
	attach(SIM_PLX_9054, SIM_PLX_OK, 0x3316);
	EXPECT_EQ(taken, 0);
	EXPECT_EQ(found.probes, 0);
}

TEST_F(Plx, Plx9030FixesReadyAndProgramsInReversedBitOrder)
{
	attach(SIM_PLX_9030, SIM_PLX_OK, 0x3131);
	ASSERT_EQ(taken, 1);
	EXPECT_FALSE(hm2_sim_plx_window_ok(&card.plx));
	hm2_plx9030_fix_ready(found.ctrl, "t");
	EXPECT_TRUE(hm2_sim_plx_window_ok(&card.plx));
	EXPECT_EQ(program9030(bitstream()), 0);
	EXPECT_TRUE(card.fpga.done);
	EXPECT_EQ(card.plx.ignored, 0u);
	// /WRITE and /LED back high, /PROGRAM high
	rtapi_u32 c = rtapi_pci_readl(found.ctrl, PLX9030_CTRL);
	EXPECT_EQ(c & (PLX9030_WRITE | PLX9030_LED | PLX9030_PROGRAM),
		  PLX9030_WRITE | PLX9030_LED | PLX9030_PROGRAM);
}

TEST_F(Plx, Plx9030RefusesAStreamInFileOrder)
{
	attach(SIM_PLX_9030, SIM_PLX_OK, 0x3131);
	std::vector<unsigned char> s = bitstream();
	for (auto &b : s)
		b = hm2_bitfile_reverse(b);	// the driver's reversal undoes it: wrong order
	EXPECT_EQ(program9030(s), -EIO);
	EXPECT_FALSE(card.fpga.done);
	EXPECT_FALSE(rtapi_pci_readl(found.ctrl, PLX9030_CTRL) & PLX9030_PROGRAM);	// held in reset
}

TEST_F(Plx, Plx9030ResetFailures)
{
	attach(SIM_PLX_9030, SIM_PLX_DONE_STUCK, 0x3131);
	EXPECT_EQ(hm2_plx9030_reset(found.ctrl, "t"), -EIO);
	TearDown();
	attach(SIM_PLX_9030, SIM_PLX_INIT_STUCK, 0x3131);
	EXPECT_EQ(hm2_plx9030_reset(found.ctrl, "t"), -EIO);
}

TEST_F(Plx, Plx9054ProgramsAndWaitsForDone)
{
	attach(SIM_PLX_9054, SIM_PLX_OK, 0x3315);
	EXPECT_EQ(program9054(bitstream()), 0);
	EXPECT_TRUE(card.fpga.done);
	rtapi_u32 c = rtapi_pci_readl(found.ctrl, PLX9054_CNTRL);
	EXPECT_EQ(c & (PLX9054_USERI_IN | PLX9054_USERO_OUT | PLX9054_PROGRAM | PLX9054_DONE),
		  PLX9054_USERI_IN | PLX9054_USERO_OUT | PLX9054_PROGRAM | PLX9054_DONE);
}

TEST_F(Plx, Plx9054Failures)
{
	attach(SIM_PLX_9054, SIM_PLX_NO_DONE, 0x3315);
	EXPECT_EQ(program9054(bitstream()), -EIO);
	TearDown();
	attach(SIM_PLX_9054, SIM_PLX_DONE_STUCK, 0x3315);
	EXPECT_EQ(hm2_plx9054_reset(found.ctrl, "t"), -EIO);
}

TEST_F(Plx, DataPortIgnoresBytesWhileTheFpgaIsInReset)
{
	attach(SIM_PLX_9054, SIM_PLX_OK, 0x3315);
	rtapi_u32 c = rtapi_pci_readl(found.ctrl, PLX9054_CNTRL) | PLX9054_USERO_OUT;
	rtapi_pci_writel(found.ctrl, PLX9054_CNTRL, c & ~PLX9054_PROGRAM);
	rtapi_pci_writeb(found.data, 0, 0x55);
	EXPECT_EQ(card.plx.ignored, 1u);
}

}  // namespace
