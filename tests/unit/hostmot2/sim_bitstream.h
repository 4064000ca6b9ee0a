// SPDX-License-Identifier: GPL-2.0-or-later
// sim_bitstream.h - a Spartan-style configuration bitstream as a .BIT file's 'e'
// chunk stores it (dummy words, sync word, frame data, DESYNC), accepted by the
// configuration-port model (sim/hm2_sim_fpgacfg.c) when sent bit-reversed.
#ifndef SIM_BITSTREAM_H
#define SIM_BITSTREAM_H

#include <cstddef>
#include <vector>

inline std::vector<unsigned char> bitstream(size_t payload = 64)
{
	std::vector<unsigned char> b = {0xFF, 0xFF, 0xFF, 0xFF, 0xAA, 0x99, 0x55, 0x66};
	for (size_t i = 0; i < payload; i++)
		b.push_back((unsigned char)(i * 37 + 11));
	for (unsigned char c : {0x30, 0x00, 0x80, 0x01, 0x00, 0x00, 0x00, 0x0D})
		b.push_back(c);
	return b;
}

#endif
