/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_bitfile.h - the one Xilinx .BIT reader every HostMot2 board driver and the
 * hm2-bitinfo tool share (format: README.md, "Mesa cards"). A .BIT file is a
 * 13-byte fixed header, then tagged chunks: 'a' design name, 'b' part name, 'c'
 * date, 'd' time (2-byte big-endian length, NUL-terminated string), 'e' the
 * configuration bitstream (4-byte big-endian length). 'b' and 'e' are required.
 * The parallel configuration ports of the Mesa cards take each bitstream byte
 * bit-reversed (hm2_bitfile_reverse). HAL-free and libc-free: the kernel module,
 * the simulated flavor, the tool and GoogleTest compile the same file. */
#ifndef HM2_BITFILE_H
#define HM2_BITFILE_H

#include "rtapi.h"

#define HM2_BITFILE_HEADER_LEN 13
#define HM2_BITFILE_STR_MAX 64		/* longest a..d string kept (longer is refused) */

struct hm2_bitfile {
	char design[HM2_BITFILE_STR_MAX];	/* 'a', "" if absent */
	char part[HM2_BITFILE_STR_MAX];		/* 'b', e.g. "3s400tq144" */
	char date[HM2_BITFILE_STR_MAX];		/* 'c' */
	char time[HM2_BITFILE_STR_MAX];		/* 'd' */
	const rtapi_u8 *data;			/* 'e': points into the caller's buffer */
	rtapi_u32 size;
};

/* Parse the size bytes at file. 0 with *bf filled, or -EINVAL with one line in err
 * (no file name: the caller adds it) saying what is wrong: "invalid header",
 * "truncated ..." (a chunk runs past the end of the file), a string chunk without
 * its NUL, an unknown chunk tag, a missing 'b' or 'e' chunk. */
int hm2_bitfile_parse(const rtapi_u8 *file, rtapi_u32 size, struct hm2_bitfile *bf, char *err,
		      int errlen);

/* 0 when the file's part name equals the board's FPGA part string (exact, as the
 * FPGA's configuration would fail on any other die); else -EINVAL with a message. */
int hm2_bitfile_check_part(const struct hm2_bitfile *bf, const char *board_part, char *err,
			   int errlen);

/* bit 0 <-> bit 7, 1 <-> 6, ...: 0x01 -> 0x80, 0x12 -> 0x48 */
static inline rtapi_u8 hm2_bitfile_reverse(rtapi_u8 b)
{
	b = (rtapi_u8)((b & 0xF0) >> 4 | (b & 0x0F) << 4);
	b = (rtapi_u8)((b & 0xCC) >> 2 | (b & 0x33) << 2);
	return (rtapi_u8)((b & 0xAA) >> 1 | (b & 0x55) << 1);
}

#endif /* HM2_BITFILE_H */
