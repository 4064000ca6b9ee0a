/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_io_uspace.c - port I/O and I/O regions (rtapi_outb(3rtapi), rtapi_region(3rtapi))
 * for the simulated-realtime flavor. A region is granted only when the process may do
 * port I/O on it (ioperm, or iopl for ports past 0xffff); a per-process table
 * refuses overlapping requests as the kernel's request_region does. Without x86 port
 * I/O every request is refused. */
#include <pthread.h>
#include <stdint.h>
#include "rtapi.h"
#include "rtapi_iosim.h"
#if defined(__x86_64__) || defined(__i386__)
#include <sys/io.h>
#define RTAPI_HAVE_PORT_IO 1
#else
#define RTAPI_HAVE_PORT_IO 0
#endif

#define RTAPI_MAX_REGIONS 32

struct io_region {
	int in_use;
	unsigned long base;
	unsigned long size;
	char name[RTAPI_NAME_LEN + 1];
};

static pthread_mutex_t region_lock = PTHREAD_MUTEX_INITIALIZER;
static struct io_region regions[RTAPI_MAX_REGIONS];

/* Each access first asks the table of simulated ranges (rtapi_iosim.c); a wide access
 * to a simulated port becomes byte accesses, lowest address first. Real port I/O
 * happens only on regions granted (ioperm) by rtapi_request_region. */
#if RTAPI_HAVE_PORT_IO
static void hw_outb(unsigned char v, unsigned int port) { outb(v, port); }
static unsigned char hw_inb(unsigned int port) { return inb(port); }
static void hw_outw(unsigned short v, unsigned int port) { outw(v, port); }
static unsigned short hw_inw(unsigned int port) { return inw(port); }
static void hw_outl(unsigned int v, unsigned int port) { outl(v, port); }
static unsigned int hw_inl(unsigned int port) { return inl(port); }
#else
/* No port I/O on this architecture; rtapi_request_region never grants real ports. */
static void hw_outb(unsigned char v, unsigned int port) {}
static unsigned char hw_inb(unsigned int port) { return 0xff; }
static void hw_outw(unsigned short v, unsigned int port) {}
static unsigned short hw_inw(unsigned int port) { return 0xffff; }
static void hw_outl(unsigned int v, unsigned int port) {}
static unsigned int hw_inl(unsigned int port) { return 0xffffffffu; }
#endif

void rtapi_outb(unsigned char byte, unsigned int port)
{
	if (!rtapi_iosim_outb(port, byte))
		hw_outb(byte, port);
}

unsigned char rtapi_inb(unsigned int port)
{
	unsigned char b;

	return rtapi_iosim_inb(port, &b) ? b : hw_inb(port);
}

void rtapi_outw(unsigned short word, unsigned int port)
{
	if (rtapi_iosim_outb(port, word & 0xff))
		rtapi_iosim_outb(port + 1, word >> 8);
	else
		hw_outw(word, port);
}

unsigned short rtapi_inw(unsigned int port)
{
	unsigned char lo, hi = 0xff;

	if (!rtapi_iosim_inb(port, &lo))
		return hw_inw(port);
	rtapi_iosim_inb(port + 1, &hi);
	return lo | (unsigned short)hi << 8;
}

void rtapi_outl(unsigned int word, unsigned int port)
{
	int i;

	if (!rtapi_iosim_outb(port, word & 0xff)) {
		hw_outl(word, port);
		return;
	}
	for (i = 1; i < 4; i++)
		rtapi_iosim_outb(port + i, (word >> (8 * i)) & 0xff);
}

unsigned int rtapi_inl(unsigned int port)
{
	unsigned char b;
	unsigned int word;
	int i;

	if (!rtapi_iosim_inb(port, &b))
		return hw_inl(port);
	word = b;
	for (i = 1; i < 4; i++) {
		b = 0xff;
		rtapi_iosim_inb(port + i, &b);
		word |= (unsigned int)b << (8 * i);
	}
	return word;
}

#if RTAPI_HAVE_PORT_IO
static int io_permit(unsigned long base, unsigned long size, int on)
{
	if (base + size <= 0x10000)
		return ioperm(base, size, on);
	return iopl(on ? 3 : 0);
}
#else
static int io_permit(unsigned long base, unsigned long size, int on)
{
	return -1;
}
#endif

static int overlaps(const struct io_region *r, unsigned long base, unsigned long size)
{
	return r->in_use && base < r->base + r->size && r->base < base + size;
}

void *rtapi_request_region(unsigned long base, unsigned long int size, const char *name)
{
	struct io_region *slot = NULL;
	int i;

	if (!name)
		name = "?";
	i = rtapi_iosim_claim(base, size, name);
	if (i)
		return i > 0 ? (void *)&rtapi_iosim_claim : NULL;
	if (size == 0 || base + size < base) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: request_region 0x%lx+%lu for '%s' refused: "
				"empty or wrapping range\n", base, size, name);
		return NULL;
	}
	pthread_mutex_lock(&region_lock);
	for (i = 0; i < RTAPI_MAX_REGIONS; i++) {
		if (overlaps(&regions[i], base, size)) {
			pthread_mutex_unlock(&region_lock);
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: request_region 0x%lx+%lu for '%s' refused: "
					"overlaps 0x%lx+%lu held by '%s'\n", base, size, name,
					regions[i].base, regions[i].size, regions[i].name);
			return NULL;
		}
		if (!regions[i].in_use && !slot)
			slot = &regions[i];
	}
	if (slot && io_permit(base, size, 1) != 0) {
		pthread_mutex_unlock(&region_lock);
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: request_region 0x%lx+%lu for '%s' refused: this "
				"process may not do port I/O (needs root / CAP_SYS_RAWIO)\n", base, size, name);
		return NULL;
	}
	if (!slot) {
		pthread_mutex_unlock(&region_lock);
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: request_region 0x%lx+%lu for '%s' refused: all %d "
				"regions in use\n", base, size, name, RTAPI_MAX_REGIONS);
		return NULL;
	}
	slot->in_use = 1;
	slot->base = base;
	slot->size = size;
	rtapi_snprintf(slot->name, sizeof(slot->name), "%s", name);
	pthread_mutex_unlock(&region_lock);
	return slot;		/* any non-NULL value means granted */
}

void rtapi_release_region(unsigned long base, unsigned long int size)
{
	int i;

	if (rtapi_iosim_release(base, size))
		return;
	pthread_mutex_lock(&region_lock);
	for (i = 0; i < RTAPI_MAX_REGIONS; i++) {
		if (regions[i].in_use && regions[i].base == base && regions[i].size == size) {
			regions[i].in_use = 0;
			if (base + size <= 0x10000)	/* iopl stays: other regions may need it */
				io_permit(base, size, 0);
			break;
		}
	}
	pthread_mutex_unlock(&region_lock);
}
