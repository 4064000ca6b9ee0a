/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_lbp16.h - LBP16, the command protocol of Mesa's Ethernet cards (hm2_eth), in
 * UDP datagrams to port 27181. A datagram holds commands back to back; each is a
 * 16-bit command word, a 16-bit byte address when the A bit is set, and the data of
 * a write. The reply is the concatenation of the data of every read, in order.
 * Everything is little-endian. Command word: bit 15 write, 14 address follows, 13
 * info area, 12..10 memory space, 9..8 element size (8/16/32/64 bit), 7 increment,
 * 6..0 element count (1..127). Spaces: 0 HostMot2 registers (32 bit), 2 EEPROM,
 * 4 timers/scratch, 6 status/control, 7 board information (16 bit).
 * Encoding for the driver, decoding for the simulator (hm2-eth-sim); HAL-free and
 * libc-free. */
#ifndef HM2_LBP16_H
#define HM2_LBP16_H

#include "rtapi.h"

#define LBP16_UDP_PORT		27181
#define LBP16_MAX_PACKET	1400	/* bytes per datagram, each direction */
#define LBP16_MAX_COUNT		127

#define LBP16_WRITE		0x8000
#define LBP16_ADDR		0x4000
#define LBP16_INFO		0x2000
#define LBP16_SPACE(n)		((n) << 10)
#define LBP16_SIZE16		0x0100
#define LBP16_SIZE32		0x0200
#define LBP16_INC		0x0080

#define LBP16_SPACE_HM2		0
#define LBP16_SPACE_EEPROM	2
#define LBP16_SPACE_TIMER	4
#define LBP16_SPACE_STATUS	6
#define LBP16_SPACE_INFO	7

/* the commands hm2_eth uses (hm2-transports notes, 3.5 and 3.6) */
#define LBP16_CMD_READ_HM2(n)	(LBP16_ADDR | LBP16_SIZE32 | LBP16_INC | (n))		/* 0x4280|n */
#define LBP16_CMD_WRITE_HM2(n)	(LBP16_WRITE | LBP16_CMD_READ_HM2(n))			/* 0xC280|n */
#define LBP16_CMD_READ_NAME	(LBP16_ADDR | LBP16_SPACE(7) | LBP16_SIZE16 | LBP16_INC | 8)	/* 0x5D88 */
#define LBP16_CMD_READ_RXCOUNT	(LBP16_ADDR | LBP16_SPACE(6) | LBP16_SIZE16 | 1)		/* 0x5901 */
#define LBP16_CMD_WRITE_SCRATCH	(LBP16_WRITE | LBP16_ADDR | LBP16_SPACE(4) | LBP16_SIZE16 | \
				 LBP16_INC | 2)						/* 0xD182 */
#define LBP16_CMD_READ_SCRATCH	(LBP16_ADDR | LBP16_SPACE(4) | LBP16_SIZE16 | LBP16_INC | 4)	/* 0x5184 */
#define LBP16_STATUS_RXCOUNT	0x0008	/* space 6: received packets */
#define LBP16_SCRATCH_READ_CNT	0x0010	/* space 4: the driver's request sequence */
#define LBP16_SCRATCH_WRITE_CNT	0x0014	/* space 4: the driver's write sequence */

struct lbp16_cmd {
	int write, has_addr, info, space, size, inc, count;	/* size in bytes: 1, 2, 4, 8 */
	rtapi_u16 addr;
};

static inline void lbp16_put16(rtapi_u8 *p, rtapi_u16 v)
{
	p[0] = (rtapi_u8)v;
	p[1] = (rtapi_u8)(v >> 8);
}

static inline void lbp16_put32(rtapi_u8 *p, rtapi_u32 v)
{
	lbp16_put16(p, (rtapi_u16)v);
	lbp16_put16(p + 2, (rtapi_u16)(v >> 16));
}

static inline rtapi_u16 lbp16_get16(const rtapi_u8 *p)
{
	return (rtapi_u16)(p[0] | p[1] << 8);
}

static inline rtapi_u32 lbp16_get32(const rtapi_u8 *p)
{
	return lbp16_get16(p) | (rtapi_u32)lbp16_get16(p + 2) << 16;
}

/* Append command word cmd (and addr when cmd has LBP16_ADDR) at buf[pos]; then
 * data_len bytes of data (a write's data, NULL for a read). The new length, or
 * -ENOSPC when it does not fit in cap bytes (nothing appended). */
int lbp16_append(rtapi_u8 *buf, int pos, int cap, rtapi_u16 cmd, rtapi_u16 addr,
		 const void *data, int data_len);

/* Decode the command at buf[pos] (len bytes in all) into *c: the position of its
 * data (or of the next command for a read), or -EINVAL for a count of 0, a
 * truncated header or a write whose data runs past len. */
int lbp16_decode(const rtapi_u8 *buf, int len, int pos, struct lbp16_cmd *c);

#endif /* HM2_LBP16_H */
