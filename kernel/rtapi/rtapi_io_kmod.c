/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_io_kmod.c - port I/O and I/O regions (rtapi_outb(3rtapi), rtapi_region(3rtapi))
 * in the kernel flavor: thin wrappers so components need no kernel headers. */
#include <linux/module.h>
#include <linux/io.h>
#include <linux/ioport.h>
#include "rtapi_kmod.h"

void rtapi_outb(unsigned char byte, unsigned int port) { outb(byte, port); }
EXPORT_SYMBOL(rtapi_outb);
unsigned char rtapi_inb(unsigned int port) { return inb(port); }
EXPORT_SYMBOL(rtapi_inb);
void rtapi_outw(unsigned short word, unsigned int port) { outw(word, port); }
EXPORT_SYMBOL(rtapi_outw);
unsigned short rtapi_inw(unsigned int port) { return inw(port); }
EXPORT_SYMBOL(rtapi_inw);
void rtapi_outl(unsigned int word, unsigned int port) { outl(word, port); }
EXPORT_SYMBOL(rtapi_outl);
unsigned int rtapi_inl(unsigned int port) { return inl(port); }
EXPORT_SYMBOL(rtapi_inl);

void *rtapi_request_region(unsigned long base, unsigned long int size, const char *name)
{
	return request_region(base, size, name);
}
EXPORT_SYMBOL(rtapi_request_region);

void rtapi_release_region(unsigned long base, unsigned long int size)
{
	release_region(base, size);
}
EXPORT_SYMBOL(rtapi_release_region);
