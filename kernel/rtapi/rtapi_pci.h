/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_pci.h - finding a PCI card and accessing one of its memory BARs, in both
 * flavors (kernel: pci_get_device/pci_iomap; simulated flavor: sysfs resourceN,
 * needs root), and simulated PCI cards (kernel/drivers/sim/) that take the place of
 * real ones: a registered simulated card is found first, and its BAR accesses call
 * the model. Init code finds and maps; rtapi_pci_readl/writel are for any context. */
#ifndef RTAPI_PCI_H
#define RTAPI_PCI_H

#include "rtapi.h"

#ifdef __cplusplus
extern "C" {
#endif

struct rtapi_pci_bar;		/* a mapped BAR; opaque */

/* Maps BAR 'bar' of the index-th (0, 1, ...) PCI function with these IDs, simulated
 * cards first, for exclusive use by 'owner' (a string that stays valid). Returns 0
 * with *map set, -ENODEV when there is no such card (no message), or another -errno
 * after a message. Init code only. */
int rtapi_pci_map_bar(unsigned int vendor, unsigned int device, int index, int bar,
		      const char *owner, struct rtapi_pci_bar **map);
void rtapi_pci_unmap_bar(struct rtapi_pci_bar *map);
/* 32-bit accesses at a byte offset; outside the BAR reads give ~0, writes nothing. */
rtapi_u32 rtapi_pci_readl(struct rtapi_pci_bar *map, unsigned long offset);
void rtapi_pci_writel(struct rtapi_pci_bar *map, unsigned long offset, rtapi_u32 value);

/* --- simulated cards --- */
#define RTAPI_PCISIM_MAX 8

struct rtapi_pcisim_ops {	/* called from the accessing context: no sleeping */
	rtapi_u32 (*readl)(void *dev, unsigned long offset);
	void (*writel)(void *dev, unsigned long offset, rtapi_u32 value);
};

/* Init code. Returns a handle >= 0, or -ENOSPC / -EINVAL after a message. */
int rtapi_pcisim_register(unsigned int vendor, unsigned int device, unsigned long bar_len,
			  const struct rtapi_pcisim_ops *ops, void *dev, const char *name);
/* Init/exit code: afterwards the callbacks are never called; a card still mapped by a
 * driver reads ~0 until unmapped. */
void rtapi_pcisim_unregister(int handle);

/* --- used by rtapi_pci_*.c only --- */
/* The index-th simulated card with these IDs (claimed for 'owner'): its handle, or
 * -ENODEV with *skipped = how many matched (to count on among real cards), or -EBUSY
 * after a message when it is already mapped. */
int rtapi_pcisim_claim(unsigned int vendor, unsigned int device, int index,
		       const char *owner, int *skipped, unsigned long *len);
void rtapi_pcisim_release(int handle);
rtapi_u32 rtapi_pcisim_readl(int handle, unsigned long offset);
void rtapi_pcisim_writel(int handle, unsigned long offset, rtapi_u32 value);

#ifdef __cplusplus
}
#endif
#endif /* RTAPI_PCI_H */
