/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_iosim.h - simulated devices behind port ranges, in both flavors.
 * A simulated device (kernel/drivers/sim/) registers a range of port addresses with
 * byte read/write callbacks; from then on rtapi_inb/outb (and the 16/32-bit forms,
 * split into byte accesses, lowest address first) on that range call the device
 * instead of the hardware, and rtapi_request_region of a range inside it is granted
 * without touching the real ports. Drivers never include this header: they run
 * unchanged against a real card or its model. */
#ifndef RTAPI_IOSIM_H
#define RTAPI_IOSIM_H

#include "rtapi.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RTAPI_IOSIM_MAX 16	/* registered ranges, all devices together */

/* Called from whatever context does the port access (usually a realtime thread):
 * no sleeping, no allocation, no locks. 'offset' is relative to the range base. */
struct rtapi_iosim_ops {
	unsigned char (*inb)(void *dev, unsigned int offset);
	void (*outb)(void *dev, unsigned int offset, unsigned char byte);
};

/* Init code only. Returns a handle >= 0, -EBUSY when the range overlaps one already
 * registered, -ENOSPC when the table is full, -EINVAL for an empty or wrapping range.
 * 'name' must stay valid until unregistered. */
int rtapi_iosim_register(unsigned int base, unsigned int size,
			 const struct rtapi_iosim_ops *ops, void *dev, const char *name);

/* Init/exit code only. After it returns the callbacks are never called again. A range
 * still claimed by a driver stays reserved (reads 0xff, writes ignored, never real
 * hardware) until the driver releases it. */
void rtapi_iosim_unregister(int handle);

/* --- used by rtapi_io_*.c only --- */
/* 1 when 'port' is simulated (the access was done), 0 when it is real hardware. */
int rtapi_iosim_inb(unsigned int port, unsigned char *byte);
int rtapi_iosim_outb(unsigned int port, unsigned char byte);
/* 1: the range lies inside one simulated range and is now claimed by 'name';
 * 0: not simulated (ask the real allocator); -EBUSY: already claimed, or it straddles
 * a simulated range's edge (the message names the holder). */
int rtapi_iosim_claim(unsigned long base, unsigned long size, const char *name);
/* 1 when the claim was on a simulated range (and is released), else 0. */
int rtapi_iosim_release(unsigned long base, unsigned long size);

#ifdef __cplusplus
}
#endif
#endif /* RTAPI_IOSIM_H */
