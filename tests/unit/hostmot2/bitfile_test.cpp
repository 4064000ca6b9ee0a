// SPDX-License-Identifier: GPL-2.0-or-later
// The Xilinx .BIT reader (hm2_bitfile.c), the board table (hm2_boards.c) and the
// simulated FPGA configuration port (sim/hm2_sim_fpgacfg.c). Every bitfile is made
// here: the fixed header, string chunks and the bitstream chunk.
#include <gtest/gtest.h>
#include <string>
#include <vector>

extern "C" {
#include "hm2_bitfile.h"
#include "hm2_boards.h"
#include "hm2_sim_fpgacfg.h"
}
#include "sim_bitstream.h"

namespace {

using Bytes = std::vector<unsigned char>;

const Bytes kHeader = {0x00, 0x09, 0x0F, 0xF0, 0x0F, 0xF0, 0x0F, 0xF0, 0x0F, 0xF0, 0x00, 0x00, 0x01};

void strChunk(Bytes &f, char tag, const std::string &s)
{
	f.push_back((unsigned char)tag);
	size_t n = s.size() + 1;
	f.push_back((unsigned char)(n >> 8));
	f.push_back((unsigned char)n);
	f.insert(f.end(), s.begin(), s.end());
	f.push_back(0);
}

Bytes bitfile(const std::string &part = "2s200pq208", const Bytes &stream = bitstream())
{
	Bytes f = kHeader;
	strChunk(f, 'a', "SVST8_4.ncd;UserID=0xFFFFFFFF");
	strChunk(f, 'b', part);
	strChunk(f, 'c', "2008/05/12");
	strChunk(f, 'd', "10:43:07");
	f.push_back('e');
	uint32_t n = (uint32_t)stream.size();
	for (int s = 24; s >= 0; s -= 8)
		f.push_back((unsigned char)(n >> s));
	f.insert(f.end(), stream.begin(), stream.end());
	return f;
}

std::string parseError(const Bytes &f)
{
	hm2_bitfile bf;
	char err[200] = "";
	EXPECT_EQ(hm2_bitfile_parse(f.data(), (rtapi_u32)f.size(), &bf, err, sizeof(err)), -EINVAL);
	return err;
}

TEST(Bitfile, ParsesHeaderFields)
{
	Bytes f = bitfile();
	hm2_bitfile bf;
	char err[200];
	ASSERT_EQ(hm2_bitfile_parse(f.data(), (rtapi_u32)f.size(), &bf, err, sizeof(err)), 0) << err;
	EXPECT_STREQ(bf.design, "SVST8_4.ncd;UserID=0xFFFFFFFF");
	EXPECT_STREQ(bf.part, "2s200pq208");
	EXPECT_STREQ(bf.date, "2008/05/12");
	EXPECT_STREQ(bf.time, "10:43:07");
	Bytes s = bitstream();
	ASSERT_EQ(bf.size, s.size());
	EXPECT_EQ(Bytes(bf.data, bf.data + bf.size), s);
	EXPECT_EQ(bf.data, f.data() + f.size() - s.size());	// points into the file
}

TEST(Bitfile, OnlyPartAndBitstreamAreRequired)
{
	Bytes f = kHeader;
	strChunk(f, 'b', "3s400tq144");
	for (unsigned char c : Bytes{'e', 0, 0, 0, 2, 0x12, 0x34})
		f.push_back(c);
	hm2_bitfile bf;
	char err[200];
	ASSERT_EQ(hm2_bitfile_parse(f.data(), (rtapi_u32)f.size(), &bf, err, sizeof(err)), 0) << err;
	EXPECT_STREQ(bf.design, "");
	EXPECT_EQ(bf.size, 2u);
}

TEST(Bitfile, RefusesAWrongHeader)
{
	Bytes f = bitfile();
	f[3] = 0x00;
	EXPECT_EQ(parseError(f), "invalid header: byte 3 is 0x00, expected 0xF0 (not a Xilinx .BIT file)");
}

TEST(Bitfile, RefusesTruncatedFiles)
{
	Bytes f = bitfile();
	EXPECT_EQ(parseError(Bytes(f.begin(), f.begin() + 5)),
		  "truncated: 5 bytes, shorter than the 13-byte .BIT header");
	// cut inside the bitstream
	Bytes cut(f.begin(), f.end() - 10);
	EXPECT_EQ(parseError(cut), "truncated: the bitstream (chunk 'e') is 80 bytes, the file has 70 left");
	// cut inside the design-name string
	EXPECT_EQ(parseError(Bytes(f.begin(), f.begin() + 20)),
		  "truncated: chunk 'a' (design name) needs 30 bytes, the file has 4 left");
	// cut right after the 'e' tag
	size_t e = f.size() - bitstream().size() - 4;
	EXPECT_EQ(parseError(Bytes(f.begin(), f.begin() + (long)e)),
		  "truncated: chunk 'e' at byte " + std::to_string(e - 1) + " has no length");
	// header and strings only
	Bytes nobits(f.begin(), f.begin() + (long)e - 1);
	EXPECT_EQ(parseError(nobits), "truncated: no bitstream (chunk 'e')");
}

TEST(Bitfile, RefusesMalformedChunks)
{
	Bytes f = kHeader;
	strChunk(f, 'a', "x");
	f.push_back('e');
	for (unsigned char c : {0, 0, 0, 1, 0xAB})
		f.push_back(c);
	EXPECT_EQ(parseError(f), "no part name (chunk 'b')");

	Bytes g = kHeader;
	g.insert(g.end(), {'b', 0, 3, 'a', 'b', 'c'});	// no NUL
	EXPECT_EQ(parseError(g), "chunk 'b' (part name) is not a NUL-terminated string");

	Bytes h = kHeader;
	h.insert(h.end(), {'z', 0, 1, 0});
	EXPECT_EQ(parseError(h), "unknown chunk tag 0x7A at byte 13 (expected 'a' to 'e')");

	Bytes k = kHeader;
	strChunk(k, 'b', "3s400tq144");
	k.insert(k.end(), {'e', 0, 0, 0, 0});
	EXPECT_EQ(parseError(k), "the bitstream (chunk 'e') is empty");
}

TEST(Bitfile, ChecksThePartName)
{
	Bytes f = bitfile("3s400tq144");
	hm2_bitfile bf;
	char err[200];
	ASSERT_EQ(hm2_bitfile_parse(f.data(), (rtapi_u32)f.size(), &bf, err, sizeof(err)), 0);
	EXPECT_EQ(hm2_bitfile_check_part(&bf, "3s400tq144", err, sizeof(err)), 0);
	EXPECT_EQ(hm2_bitfile_check_part(&bf, "3s200tq144", err, sizeof(err)), -EINVAL);
	EXPECT_STREQ(err, "wrong part: the file is for a 3s400tq144 FPGA, this board has a 3s200tq144");
	EXPECT_EQ(hm2_bitfile_check_part(&bf, nullptr, err, sizeof(err)), -EINVAL);
}

TEST(Bitfile, ReversesBits)
{
	EXPECT_EQ(hm2_bitfile_reverse(0x01), 0x80);
	EXPECT_EQ(hm2_bitfile_reverse(0x0F), 0xF0);
	EXPECT_EQ(hm2_bitfile_reverse(0x5A), 0x5A);
	EXPECT_EQ(hm2_bitfile_reverse(0x12), 0x48);
	EXPECT_EQ(hm2_bitfile_reverse(0xAA), 0x55);
	for (int b = 0; b < 256; b++) {
		int r = 0;
		for (int i = 0; i < 8; i++)
			r |= ((b >> i) & 1) << (7 - i);
		EXPECT_EQ(hm2_bitfile_reverse((rtapi_u8)b), r) << b;
	}
}

TEST(Boards, TableAnswersWhichBoardsFitAPart)
{
	const hm2_board_info *b = hm2_board_find("5i20");
	ASSERT_NE(b, nullptr);
	EXPECT_EQ(b->config, HM2_CFG_PLX9030);
	EXPECT_EQ(b->connectors, 3);
	EXPECT_STREQ(b->connector[0], "P2");
	EXPECT_TRUE(hm2_board_fits(b, "2s200pq208"));
	EXPECT_FALSE(hm2_board_fits(b, "3s400pq208"));
	EXPECT_TRUE(hm2_board_fits(hm2_board_find("7i43"), "3s200tq144"));
	EXPECT_TRUE(hm2_board_fits(hm2_board_find("7i43"), "3s400tq144"));
	EXPECT_TRUE(hm2_board_fits(hm2_board_find("5i22"), "3s1500fg320"));
	// flash boards take no bitfile, whatever the part
	EXPECT_FALSE(hm2_board_fits(hm2_board_find("5i25"), "6slx9tqg144"));
	EXPECT_EQ(hm2_board_find("7i92"), nullptr);
	std::string fits;
	const hm2_board_info *i;
	for (int n = 0; (i = hm2_board_at(n)); n++)
		if (hm2_board_fits(i, "3s400pq208"))
			fits += std::string(fits.empty() ? "" : ",") + i->name;
	EXPECT_EQ(fits, "5i21,5i23,4i68");
}

// The configuration port sees each byte as sent; the card's wiring wants it reversed.
TEST(FpgaCfg, DoneOnlyForTheReversedBitstream)
{
	Bytes s = bitstream();
	hm2_sim_fpgacfg c;
	hm2_sim_fpgacfg_clear(&c);
	for (unsigned char b : s)
		hm2_sim_fpgacfg_byte(&c, hm2_bitfile_reverse(b));
	EXPECT_TRUE(c.done);
	EXPECT_EQ(c.bytes, s.size());

	hm2_sim_fpgacfg_clear(&c);
	for (unsigned char b : s)
		hm2_sim_fpgacfg_byte(&c, b);	// file order: the sync word is never seen
	EXPECT_FALSE(c.done);
	EXPECT_FALSE(c.synced);

	Bytes nodesync(s.begin(), s.end() - 8);
	hm2_sim_fpgacfg_clear(&c);
	for (unsigned char b : nodesync)
		hm2_sim_fpgacfg_byte(&c, hm2_bitfile_reverse(b));
	EXPECT_TRUE(c.synced);
	EXPECT_FALSE(c.done);
}

}  // namespace
