/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_bitfile.c - the Xilinx .BIT reader (hm2_bitfile.h). */
#include "rtapi.h"
#include "rtapi_string.h"
#include "hm2_bitfile.h"

static const rtapi_u8 bit_header[HM2_BITFILE_HEADER_LEN] = {
	0x00, 0x09, 0x0F, 0xF0, 0x0F, 0xF0, 0x0F, 0xF0, 0x0F, 0xF0, 0x00, 0x00, 0x01
};

static char *string_field(struct hm2_bitfile *bf, int tag)
{
	switch (tag) {
	case 'a': return bf->design;
	case 'b': return bf->part;
	case 'c': return bf->date;
	default: return bf->time;
	}
}

static const char *string_name(int tag)
{
	switch (tag) {
	case 'a': return "design name";
	case 'b': return "part name";
	case 'c': return "date";
	default: return "time";
	}
}

int hm2_bitfile_parse(const rtapi_u8 *file, rtapi_u32 size, struct hm2_bitfile *bf, char *err,
		      int errlen)
{
	rtapi_u32 pos = HM2_BITFILE_HEADER_LEN, len;
	int i, have_part = 0;

	memset(bf, 0, sizeof(*bf));
	if (size < HM2_BITFILE_HEADER_LEN) {
		rtapi_snprintf(err, errlen, "truncated: %u bytes, shorter than the %d-byte .BIT header",
			       size, HM2_BITFILE_HEADER_LEN);
		return -EINVAL;
	}
	for (i = 0; i < HM2_BITFILE_HEADER_LEN; i++) {
		if (file[i] != bit_header[i]) {
			rtapi_snprintf(err, errlen, "invalid header: byte %d is 0x%02X, expected 0x%02X "
				       "(not a Xilinx .BIT file)", i, file[i], bit_header[i]);
			return -EINVAL;
		}
	}
	while (pos < size) {
		int tag = file[pos++];

		if (tag >= 'a' && tag <= 'd') {
			char *dst = string_field(bf, tag);

			if (size - pos < 2) {
				rtapi_snprintf(err, errlen, "truncated: chunk '%c' at byte %u has no "
					       "length", tag, pos - 1);
				return -EINVAL;
			}
			len = (rtapi_u32)file[pos] << 8 | file[pos + 1];
			pos += 2;
			if (len > size - pos) {
				rtapi_snprintf(err, errlen, "truncated: chunk '%c' (%s) needs %u bytes, "
					       "the file has %u left", tag, string_name(tag), len,
					       size - pos);
				return -EINVAL;
			}
			if (len == 0 || file[pos + len - 1] != 0) {
				rtapi_snprintf(err, errlen, "chunk '%c' (%s) is not a NUL-terminated "
					       "string", tag, string_name(tag));
				return -EINVAL;
			}
			if (len > HM2_BITFILE_STR_MAX) {
				rtapi_snprintf(err, errlen, "chunk '%c' (%s) is %u bytes, longer than "
					       "%d", tag, string_name(tag), len, HM2_BITFILE_STR_MAX);
				return -EINVAL;
			}
			memcpy(dst, file + pos, len);
			if (tag == 'b')
				have_part = 1;
			pos += len;
		} else if (tag == 'e') {
			if (size - pos < 4) {
				rtapi_snprintf(err, errlen, "truncated: chunk 'e' at byte %u has no "
					       "length", pos - 1);
				return -EINVAL;
			}
			len = (rtapi_u32)file[pos] << 24 | (rtapi_u32)file[pos + 1] << 16 |
			      (rtapi_u32)file[pos + 2] << 8 | file[pos + 3];
			pos += 4;
			if (len > size - pos) {
				rtapi_snprintf(err, errlen, "truncated: the bitstream (chunk 'e') is "
					       "%u bytes, the file has %u left", len, size - pos);
				return -EINVAL;
			}
			if (len == 0) {
				rtapi_snprintf(err, errlen, "the bitstream (chunk 'e') is empty");
				return -EINVAL;
			}
			bf->data = file + pos;
			bf->size = len;
			break;	/* the bitstream is the last chunk; anything after it is ignored */
		} else {
			rtapi_snprintf(err, errlen, "unknown chunk tag 0x%02X at byte %u (expected 'a' "
				       "to 'e')", tag, pos - 1);
			return -EINVAL;
		}
	}
	if (!have_part) {
		rtapi_snprintf(err, errlen, "no part name (chunk 'b')");
		return -EINVAL;
	}
	if (!bf->data) {
		rtapi_snprintf(err, errlen, "truncated: no bitstream (chunk 'e')");
		return -EINVAL;
	}
	return 0;
}

int hm2_bitfile_check_part(const struct hm2_bitfile *bf, const char *board_part, char *err,
			   int errlen)
{
	if (!board_part || strcmp(bf->part, board_part) != 0) {
		rtapi_snprintf(err, errlen, "wrong part: the file is for a %s FPGA, this board has a %s",
			       bf->part, board_part ? board_part : "(unknown)");
		return -EINVAL;
	}
	return 0;
}
