// SPDX-License-Identifier: GPL-2.0-or-later
// hm2_7i43's EPP cycles (hm2_7i43_epp.c) against the worked example of the transport
// notes (hm2-transports.md 2.4): the exact port accesses of a cookie read and of a
// watchdog write, byte and wide mode, and the timeout flag's clearing. A fake port
// behind rtapi_iosim records every access.
#include <gtest/gtest.h>
#include <vector>

extern "C" {
#include "rtapi_iosim.h"
#include "hm2_7i43_epp.h"
}

namespace {

constexpr unsigned base = 0x2000;

struct Access {
	char dir;		// 'i' or 'o'
	unsigned offset;
	unsigned char byte;
	bool operator==(const Access &) const = default;
};

struct FakePort {
	std::vector<Access> log;
	std::vector<unsigned char> data_in;	// what EPP data reads return, in order
	unsigned char status = 0;
};

unsigned char fake_inb(void *dev, unsigned offset)
{
	auto *p = static_cast<FakePort *>(dev);
	unsigned char b = 0xFF;
	if (offset == 1)
		b = p->status;
	else if (offset >= 4 && !p->data_in.empty()) {
		b = p->data_in.front();
		p->data_in.erase(p->data_in.begin());
	}
	p->log.push_back({'i', offset, b});
	return b;
}

void fake_outb(void *dev, unsigned offset, unsigned char b)
{
	auto *p = static_cast<FakePort *>(dev);
	if (offset == 1 && (b & 1))
		p->status = 0;
	p->log.push_back({'o', offset, b});
}

const rtapi_iosim_ops ops = {fake_inb, fake_outb};

class Epp : public ::testing::Test {
protected:
	void SetUp() override
	{
		handle = rtapi_iosim_register(base, 8, &ops, &port, "epp-test");
		ASSERT_GE(handle, 0);
	}
	void TearDown() override { rtapi_iosim_unregister(handle); }
	FakePort port;
	epp_port epp{base, 0, 0, "hm2_7i43.0"};
	int handle = -1;
};

TEST_F(Epp, CookieReadInByteMode)
{
	port.data_in = {0xFE, 0xCA, 0xAA, 0x55};
	rtapi_u32 w = 0;
	epp_read_words(&epp, 0x0100, &w, 1);
	EXPECT_EQ(w, 0x55AACAFEu);
	std::vector<Access> want = {{'o', 3, 0x00}, {'o', 3, 0x81}, {'i', 4, 0xFE},
				    {'i', 4, 0xCA}, {'i', 4, 0xAA}, {'i', 4, 0x55}};
	EXPECT_EQ(port.log, want);
}

TEST_F(Epp, WatchdogWriteCommitsOnTheFourthByte)
{
	rtapi_u32 w = 0x5A000000;
	epp_write_words(&epp, 0x0E00, &w, 1);
	std::vector<Access> want = {{'o', 3, 0x00}, {'o', 3, 0x8E}, {'o', 4, 0x00},
				    {'o', 4, 0x00}, {'o', 4, 0x00}, {'o', 4, 0x5A}};
	EXPECT_EQ(port.log, want);
}

TEST_F(Epp, WideModeIsFourDataCyclesLsbFirst)
{
	epp.wide = 1;
	port.data_in = {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08};
	rtapi_u32 w[2] = {};
	epp_read_words(&epp, 0x1000, w, 2);
	EXPECT_EQ(w[0], 0x04030201u);
	EXPECT_EQ(w[1], 0x08070605u);
	ASSERT_EQ(port.log.size(), 10u);
	EXPECT_EQ(port.log[1], (Access{'o', 3, 0x90}));	// 0x10 | auto-increment
	for (int i = 0; i < 8; i++)
		EXPECT_EQ(port.log[2 + i].offset, 4u + i % 4);	// a 32-bit access at base+4
}

TEST_F(Epp, TimeoutFlagIsReportedOnceAndCleared)
{
	EXPECT_EQ(epp_timed_out(&epp), 0);
	EXPECT_EQ(port.log.size(), 1u);		// one status read when all is well
	port.status = 0x01;
	EXPECT_EQ(epp_timed_out(&epp), 1);
	EXPECT_EQ(port.log.back(), (Access{'o', 1, 0x00}));	// write 1, then 0
	EXPECT_EQ(port.log[port.log.size() - 2], (Access{'o', 1, 0x01}));
	EXPECT_EQ(epp_timed_out(&epp), 0);
}

}  // namespace
