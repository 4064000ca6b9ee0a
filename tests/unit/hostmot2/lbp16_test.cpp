// SPDX-License-Identifier: GPL-2.0-or-later
// LBP16 framing (hm2_lbp16.c) against the worked byte examples of the transport
// notes: the commands hm2_eth sends, and the simulator's decoding of them.
#include <gtest/gtest.h>
#include <vector>

extern "C" {
#include "hm2_lbp16.h"
}

namespace {

using Bytes = std::vector<unsigned char>;

Bytes append(Bytes b, rtapi_u16 cmd, rtapi_u16 addr, const Bytes &data = {})
{
	size_t pos = b.size();
	b.resize(pos + 4 + data.size());
	int n = lbp16_append(b.data(), (int)pos, (int)b.size(), cmd, addr,
			     data.empty() ? nullptr : data.data(), (int)data.size());
	EXPECT_GT(n, 0);
	b.resize((size_t)n);
	return b;
}

TEST(Lbp16, CommandWordsOfTheNotes)
{
	EXPECT_EQ(LBP16_CMD_READ_HM2(1), 0x4281);
	EXPECT_EQ(LBP16_CMD_WRITE_HM2(1), 0xC281);
	EXPECT_EQ(LBP16_CMD_READ_NAME, 0x5D88);
	EXPECT_EQ(LBP16_CMD_READ_RXCOUNT, 0x5901);
	EXPECT_EQ(LBP16_CMD_WRITE_SCRATCH, 0xD182);
	EXPECT_EQ(LBP16_CMD_READ_SCRATCH, 0x5184);
	EXPECT_EQ(LBP16_UDP_PORT, 27181);
}

TEST(Lbp16, ReadTheCookie)
{
	EXPECT_EQ(append({}, LBP16_CMD_READ_HM2(1), 0x0100), (Bytes{0x81, 0x42, 0x00, 0x01}));
	EXPECT_EQ(lbp16_get32(Bytes{0xFE, 0xCA, 0xAA, 0x55}.data()), 0x55AACAFEu);
}

TEST(Lbp16, ReadThreeIoPortWordsAndTheBoardName)
{
	EXPECT_EQ(append({}, LBP16_CMD_READ_HM2(3), 0x1000), (Bytes{0x83, 0x42, 0x00, 0x10}));
	EXPECT_EQ(append({}, LBP16_CMD_READ_NAME, 0), (Bytes{0x88, 0x5D, 0x00, 0x00}));
}

TEST(Lbp16, PetTheWatchdog)
{
	unsigned char d[4];
	lbp16_put32(d, 0x5A000000);
	Bytes data(d, d + 4);
	EXPECT_EQ(data, (Bytes{0x00, 0x00, 0x00, 0x5A}));
	EXPECT_EQ(append({}, LBP16_CMD_WRITE_HM2(1), 0x0E00, data),
		  (Bytes{0x81, 0xC2, 0x00, 0x0E, 0x00, 0x00, 0x00, 0x5A}));
}

TEST(Lbp16, RequestAndWriteTrailers)
{
	Bytes cnt = {0x11, 0x22, 0x33, 0x44};
	EXPECT_EQ(append({}, LBP16_CMD_WRITE_SCRATCH, LBP16_SCRATCH_WRITE_CNT, cnt),
		  (Bytes{0x82, 0xD1, 0x14, 0x00, 0x11, 0x22, 0x33, 0x44}));
	Bytes r = append({}, LBP16_CMD_READ_RXCOUNT, LBP16_STATUS_RXCOUNT);
	r = append(r, LBP16_CMD_WRITE_SCRATCH, LBP16_SCRATCH_READ_CNT, cnt);
	r = append(r, LBP16_CMD_READ_SCRATCH, LBP16_SCRATCH_READ_CNT);
	EXPECT_EQ(r, (Bytes{0x01, 0x59, 0x08, 0x00, 0x82, 0xD1, 0x10, 0x00, 0x11, 0x22, 0x33, 0x44,
			    0x84, 0x51, 0x10, 0x00}));
}

TEST(Lbp16, AppendRefusesWhatDoesNotFit)
{
	unsigned char buf[6];
	EXPECT_EQ(lbp16_append(buf, 0, 6, LBP16_CMD_READ_HM2(1), 0x100, nullptr, 0), 4);
	EXPECT_EQ(lbp16_append(buf, 4, 6, LBP16_CMD_READ_HM2(1), 0x100, nullptr, 0), -ENOSPC);
	unsigned char d[4] = {};
	EXPECT_EQ(lbp16_append(buf, 0, 6, LBP16_CMD_WRITE_HM2(1), 0xE00, d, 4), -ENOSPC);
}

TEST(Lbp16, DecodesEveryField)
{
	Bytes w = {0x81, 0xC2, 0x00, 0x0E, 0x00, 0x00, 0x00, 0x5A};
	lbp16_cmd c;
	ASSERT_EQ(lbp16_decode(w.data(), (int)w.size(), 0, &c), 4);
	EXPECT_TRUE(c.write);
	EXPECT_TRUE(c.has_addr);
	EXPECT_FALSE(c.info);
	EXPECT_EQ(c.space, 0);
	EXPECT_EQ(c.size, 4);
	EXPECT_TRUE(c.inc);
	EXPECT_EQ(c.count, 1);
	EXPECT_EQ(c.addr, 0x0E00);

	Bytes n = {0x88, 0x5D, 0x00, 0x00};
	ASSERT_EQ(lbp16_decode(n.data(), 4, 0, &c), 4);
	EXPECT_FALSE(c.write);
	EXPECT_EQ(c.space, 7);
	EXPECT_EQ(c.size, 2);
	EXPECT_EQ(c.count, 8);

	// info area read without address: 0x2000 | space 2 | 16-bit | count 1
	Bytes i = {0x01, 0x29};
	ASSERT_EQ(lbp16_decode(i.data(), 2, 0, &c), 2);
	EXPECT_TRUE(c.info);
	EXPECT_FALSE(c.has_addr);
	EXPECT_EQ(c.space, 2);
}

TEST(Lbp16, DecodeRefusesMalformedCommands)
{
	lbp16_cmd c;
	Bytes zero = {0x80, 0x42, 0x00, 0x01};	// count 0
	EXPECT_EQ(lbp16_decode(zero.data(), 4, 0, &c), -EINVAL);
	Bytes noaddr = {0x81, 0x42, 0x00};
	EXPECT_EQ(lbp16_decode(noaddr.data(), 3, 0, &c), -EINVAL);
	Bytes shortdata = {0x82, 0xC2, 0x00, 0x0E, 1, 2, 3, 4, 5};	// 2 words promised, 5 bytes
	EXPECT_EQ(lbp16_decode(shortdata.data(), 9, 0, &c), -EINVAL);
	EXPECT_EQ(lbp16_decode(shortdata.data(), 9, 8, &c), -EINVAL);	// one byte left
}

}  // namespace
