// SPDX-License-Identifier: GPL-2.0-or-later
// hm2-bitinfo - prints a Xilinx .BIT file's header (design, part, date, time,
// bitstream size) and the Mesa boards whose FPGA it fits, with the same reader the
// drivers use (kernel/drivers/hostmot2/hm2_bitfile.c). Exit status: 0 for a valid
// file, 1 when it is not a usable bitfile (the reason on stderr), 2 for usage.
//   hm2-bitinfo FILE...
//   hm2-bitinfo --board 5i20 FILE   also checks it fits that board (exit 1 if not)
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" {
#include "hm2_bitfile.h"
#include "hm2_boards.h"
}

namespace {

int usage()
{
	std::fprintf(stderr, "usage: hm2-bitinfo [--board BOARD] FILE.bit...\n");
	return 2;
}

std::string fitting_boards(const char *part)
{
	std::string s;
	const hm2_board_info *b;
	for (int i = 0; (b = hm2_board_at(i)); i++) {
		if (hm2_board_fits(b, part)) {
			if (!s.empty())
				s += ", ";
			s += b->name;
		}
	}
	return s;
}

int show(const char *path, const char *board)
{
	std::ifstream in(path, std::ios::binary);
	if (!in) {
		std::fprintf(stderr, "hm2-bitinfo: %s: cannot open: %s\n", path, std::strerror(errno));
		return 1;
	}
	std::vector<unsigned char> data((std::istreambuf_iterator<char>(in)),
					std::istreambuf_iterator<char>());
	if (data.size() > 0xFFFFFFFFu) {
		std::fprintf(stderr, "hm2-bitinfo: %s: larger than 4 GiB\n", path);
		return 1;
	}
	hm2_bitfile bf;
	char err[200];
	if (hm2_bitfile_parse(data.data(), (rtapi_u32)data.size(), &bf, err, sizeof(err))) {
		std::fprintf(stderr, "hm2-bitinfo: %s: %s\n", path, err);
		return 1;
	}
	std::string fits = fitting_boards(bf.part);
	std::printf("%s:\n  design:    %s\n  part:      %s\n  date:      %s %s\n"
		    "  bitstream: %u bytes\n  boards:    %s\n", path, bf.design, bf.part, bf.date,
		    bf.time, bf.size, fits.empty() ? "none (no programmable Mesa board has this FPGA)"
						   : fits.c_str());
	if (board) {
		const hm2_board_info *b = hm2_board_find(board);
		if (!b) {
			std::fprintf(stderr, "hm2-bitinfo: --board %s: unknown board\n", board);
			return 1;
		}
		if (b->config == HM2_CFG_FLASH) {
			std::fprintf(stderr, "hm2-bitinfo: %s boots from its flash: firmware= is "
				     "ignored for it (use mesaflash)\n", board);
			return 1;
		}
		if (hm2_bitfile_check_part(&bf, b->part[0], err, sizeof(err)) &&
		    !hm2_board_fits(b, bf.part)) {
			std::fprintf(stderr, "hm2-bitinfo: %s: does not fit the %s: %s\n", path, board, err);
			return 1;
		}
		std::printf("  fits the %s\n", board);
	}
	return 0;
}

}  // namespace

int main(int argc, char **argv)
{
	const char *board = nullptr;
	int i = 1, status = 0;
	std::setvbuf(stdout, nullptr, _IOLBF, 0);	// reports and errors in file order
	if (i < argc && std::strcmp(argv[i], "--board") == 0) {
		if (i + 1 >= argc)
			return usage();
		board = argv[i + 1];
		i += 2;
	}
	if (i >= argc || argv[i][0] == '-')
		return usage();
	for (; i < argc; i++)
		if (show(argv[i], board))
			status = 1;
	return status;
}
