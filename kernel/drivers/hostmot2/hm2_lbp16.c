/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_lbp16.c - LBP16 command encoding and decoding (hm2_lbp16.h). */
#include "rtapi.h"
#include "rtapi_string.h"
#include "hm2_lbp16.h"

int lbp16_append(rtapi_u8 *buf, int pos, int cap, rtapi_u16 cmd, rtapi_u16 addr,
		 const void *data, int data_len)
{
	int need = 2 + ((cmd & LBP16_ADDR) ? 2 : 0) + data_len;

	if (pos < 0 || need > cap - pos)
		return -ENOSPC;
	lbp16_put16(buf + pos, cmd);
	pos += 2;
	if (cmd & LBP16_ADDR) {
		lbp16_put16(buf + pos, addr);
		pos += 2;
	}
	if (data_len) {
		memcpy(buf + pos, data, data_len);
		pos += data_len;
	}
	return pos;
}

int lbp16_decode(const rtapi_u8 *buf, int len, int pos, struct lbp16_cmd *c)
{
	rtapi_u16 w;

	if (pos < 0 || len - pos < 2)
		return -EINVAL;
	w = lbp16_get16(buf + pos);
	pos += 2;
	c->write = !!(w & LBP16_WRITE);
	c->has_addr = !!(w & LBP16_ADDR);
	c->info = !!(w & LBP16_INFO);
	c->space = (w >> 10) & 7;
	c->size = 1 << ((w >> 8) & 3);
	c->inc = !!(w & LBP16_INC);
	c->count = w & 0x7F;
	c->addr = 0;
	if (c->count == 0)
		return -EINVAL;
	if (c->has_addr) {
		if (len - pos < 2)
			return -EINVAL;
		c->addr = lbp16_get16(buf + pos);
		pos += 2;
	}
	if (c->write && len - pos < c->count * c->size)
		return -EINVAL;
	return pos;
}
