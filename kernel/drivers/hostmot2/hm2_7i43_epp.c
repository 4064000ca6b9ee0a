/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_7i43_epp.c - EPP cycles to a 7i43 (hm2_7i43_epp.h). */
#include "rtapi.h"
#include "hm2_7i43_epp.h"

#define STATUS 1
#define EPP_ADDR 3
#define EPP_DATA 4
#define STATUS_TIMEOUT 0x01

void epp_addr8(const struct epp_port *p, rtapi_u8 addr)
{
	rtapi_outb(addr, p->base + EPP_ADDR);
}

void epp_write8(const struct epp_port *p, rtapi_u8 byte)
{
	rtapi_outb(byte, p->base + EPP_DATA);
}

rtapi_u8 epp_read8(const struct epp_port *p)
{
	return rtapi_inb(p->base + EPP_DATA);
}

/* low byte first; the firmware takes the next address write as the high byte */
static void epp_addr16(const struct epp_port *p, rtapi_u32 addr)
{
	epp_addr8(p, (rtapi_u8)(addr & 0xFF));
	epp_addr8(p, (rtapi_u8)((addr >> 8) | (EPP_AUTOINC >> 8)));
}

void epp_read_words(const struct epp_port *p, rtapi_u32 addr, rtapi_u32 *buf, int words)
{
	int i, lane;

	epp_addr16(p, addr);
	for (i = 0; i < words; i++) {
		if (p->wide)
			buf[i] = rtapi_inl(p->base + EPP_DATA);
		else	/* lane 0 makes the firmware fetch the word */
			for (buf[i] = 0, lane = 0; lane < 4; lane++)
				buf[i] |= (rtapi_u32)epp_read8(p) << 8 * lane;
		if (p->debug)
			rtapi_print("%s: EPP read 0x%04x = 0x%08x\n", p->name, addr + 4 * i, buf[i]);
	}
}

void epp_write_words(const struct epp_port *p, rtapi_u32 addr, const rtapi_u32 *buf, int words)
{
	int i, lane;

	epp_addr16(p, addr);
	for (i = 0; i < words; i++) {
		if (p->debug)
			rtapi_print("%s: EPP write 0x%04x = 0x%08x\n", p->name, addr + 4 * i, buf[i]);
		if (p->wide)
			rtapi_outl(buf[i], p->base + EPP_DATA);
		else	/* the byte for lane 3 commits the 32-bit write */
			for (lane = 0; lane < 4; lane++)
				epp_write8(p, (rtapi_u8)(buf[i] >> 8 * lane));
	}
}

int epp_timed_out(const struct epp_port *p)
{
	unsigned int status = p->base + STATUS;

	if (!(rtapi_inb(status) & STATUS_TIMEOUT))
		return 0;
	rtapi_inb(status);	/* some ports clear it on read, */
	rtapi_inb(status);
	rtapi_outb(STATUS_TIMEOUT, status);	/* some on writing 1, */
	rtapi_outb(0, status);			/* others on writing 0 */
	return 1;
}
