/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_io_kmod.c - port I/O and I/O regions (rtapi_outb(3rtapi), rtapi_region(3rtapi))
 * in the kernel flavor: thin wrappers so components need no kernel headers. */
#include <linux/module.h>
#include <linux/io.h>
#include <linux/ioport.h>
#include "rtapi_kmod.h"
#include "rtapi_iosim.h"

/* Each access first asks the table of simulated ranges (rtapi_iosim.c); a wide access
 * to a simulated port becomes byte accesses, lowest address first, as an 8-bit bus
 * (the parallel port's EPP data register) splits it. */
void rtapi_outb(unsigned char byte, unsigned int port)
{
	if (!rtapi_iosim_outb(port, byte))
		outb(byte, port);
}
EXPORT_SYMBOL(rtapi_outb);

unsigned char rtapi_inb(unsigned int port)
{
	unsigned char b;

	return rtapi_iosim_inb(port, &b) ? b : inb(port);
}
EXPORT_SYMBOL(rtapi_inb);

void rtapi_outw(unsigned short word, unsigned int port)
{
	if (rtapi_iosim_outb(port, word & 0xff))
		rtapi_iosim_outb(port + 1, word >> 8);
	else
		outw(word, port);
}
EXPORT_SYMBOL(rtapi_outw);

unsigned short rtapi_inw(unsigned int port)
{
	unsigned char lo, hi = 0xff;

	if (!rtapi_iosim_inb(port, &lo))
		return inw(port);
	rtapi_iosim_inb(port + 1, &hi);
	return lo | (unsigned short)hi << 8;
}
EXPORT_SYMBOL(rtapi_inw);

void rtapi_outl(unsigned int word, unsigned int port)
{
	int i;

	if (!rtapi_iosim_outb(port, word & 0xff)) {
		outl(word, port);
		return;
	}
	for (i = 1; i < 4; i++)
		rtapi_iosim_outb(port + i, (word >> (8 * i)) & 0xff);
}
EXPORT_SYMBOL(rtapi_outl);

unsigned int rtapi_inl(unsigned int port)
{
	unsigned char b;
	unsigned int word;
	int i;

	if (!rtapi_iosim_inb(port, &b))
		return inl(port);
	word = b;
	for (i = 1; i < 4; i++) {
		b = 0xff;
		rtapi_iosim_inb(port + i, &b);
		word |= (unsigned int)b << (8 * i);
	}
	return word;
}
EXPORT_SYMBOL(rtapi_inl);

EXPORT_SYMBOL(rtapi_iosim_register);
EXPORT_SYMBOL(rtapi_iosim_unregister);

/* A range inside a simulated device is claimed there, never from the kernel's
 * resource tree (qemu or a real machine may have hardware at the same address). */
void *rtapi_request_region(unsigned long base, unsigned long int size, const char *name)
{
	int sim = rtapi_iosim_claim(base, size, name);

	if (sim)
		return sim > 0 ? (void *)&rtapi_iosim_claim : NULL;
	if (!request_region(base, size, name)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: request_region 0x%lx+%lu for '%s' refused: "
				"busy (see /proc/ioports)\n", base, size, name);
		return NULL;
	}
	return (void *)&rtapi_iosim_claim;	/* any non-NULL value means granted */
}
EXPORT_SYMBOL(rtapi_request_region);

void rtapi_release_region(unsigned long base, unsigned long int size)
{
	if (!rtapi_iosim_release(base, size))
		release_region(base, size);
}
EXPORT_SYMBOL(rtapi_release_region);
