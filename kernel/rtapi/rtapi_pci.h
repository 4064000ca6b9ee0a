/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_pci.h - finding PCI cards and accessing their BARs, in both flavors (kernel:
 * pci_get_device or a pci_driver, pci_iomap; simulated flavor: sysfs resourceN, needs
 * root), and simulated PCI cards (kernel/drivers/sim/, kernel/drivers/hostmot2/sim/)
 * that take the place of real ones: a registered simulated card is found first, and
 * its BAR accesses call the model. Two ways to find cards: rtapi_pci_map_bar (one
 * memory BAR of the index-th card with a vendor:device) for simple cards, and
 * rtapi_pci_register_driver (every card matching a table of vendor, device and
 * subsystem IDs, handed to the driver's probe, which maps the memory and I/O BARs it
 * needs) for cards behind a bridge. Init code finds and maps; the accessors are for
 * any context. Simulated flavor: HAL_PCI_SYSFS_DIR names another directory laid out
 * like /sys/bus/pci/devices (tests/unit/rtapi/rtapi_pci_test.cpp). */
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
/* 32-bit and 8-bit accesses at a byte offset, to a memory BAR or an I/O BAR (inl,
 * outb); outside the BAR reads give ~0, writes nothing. */
rtapi_u32 rtapi_pci_readl(struct rtapi_pci_bar *map, unsigned long offset);
void rtapi_pci_writel(struct rtapi_pci_bar *map, unsigned long offset, rtapi_u32 value);
rtapi_u8 rtapi_pci_readb(struct rtapi_pci_bar *map, unsigned long offset);
void rtapi_pci_writeb(struct rtapi_pci_bar *map, unsigned long offset, rtapi_u8 value);

/* --- drivers: cards matched by all four IDs --- */
struct rtapi_pci_id {
	unsigned int vendor, device, subvendor, subdevice;
};

struct rtapi_pci_dev;		/* one card taken by a driver; opaque */

struct rtapi_pci_driver {
	const char *name;			/* owner of the cards, "hm2_pci" */
	const struct rtapi_pci_id *ids;		/* ends with vendor 0 */
	/* A matching card, simulated cards first, then real ones in bus order. 0: taken;
	 * > 0: declined (left alone, not counted); < 0: failed after a message. */
	int (*probe)(struct rtapi_pci_dev *dev, const struct rtapi_pci_id *id);
	void (*remove)(struct rtapi_pci_dev *dev);	/* a taken card, at unregister */
	void *rtapi;				/* rtapi's, set by register */
};

/* Registers drv and probes every matching card (kernel flavor: as a pci_driver, so
 * a card bound to another driver is not offered). Returns how many cards were taken
 * (>= 0), or the first probe failure's -errno after removing the cards taken and
 * unregistering. Init code only. */
int rtapi_pci_register_driver(struct rtapi_pci_driver *drv);
/* Removes every card taken (drv->remove), then forgets drv. Exit code only. */
void rtapi_pci_unregister_driver(struct rtapi_pci_driver *drv);
/* Maps BAR 'bar' (memory or I/O) of a taken card: 0, or -errno after a message.
 * Unmap with rtapi_pci_unmap_bar before remove returns. Probe/remove only. */
int rtapi_pci_dev_map_bar(struct rtapi_pci_dev *dev, int bar, struct rtapi_pci_bar **map);
/* "0000:03:00.0", or "sim:NAME" for a simulated card: for messages. */
const char *rtapi_pci_dev_name(const struct rtapi_pci_dev *dev);
void rtapi_pci_set_drvdata(struct rtapi_pci_dev *dev, void *data);
void *rtapi_pci_get_drvdata(const struct rtapi_pci_dev *dev);

/* --- simulated cards --- */
#define RTAPI_PCISIM_MAX 8
#define RTAPI_PCI_BARS 6

struct rtapi_pcisim_ops {	/* called from the accessing context: no sleeping */
	/* BAR 0 of a card registered with rtapi_pcisim_register, 32-bit accesses */
	rtapi_u32 (*readl)(void *dev, unsigned long offset);
	void (*writel)(void *dev, unsigned long offset, rtapi_u32 value);
	/* any BAR of a card registered with rtapi_pcisim_register_card; size 1 or 4 */
	rtapi_u32 (*read)(void *dev, int bar, unsigned long offset, int size);
	void (*write)(void *dev, int bar, unsigned long offset, int size, rtapi_u32 value);
};

/* what a simulated card shows of itself: IDs and the length of each BAR (0: none) */
struct rtapi_pcisim_card {
	struct rtapi_pci_id id;
	unsigned long bar_len[RTAPI_PCI_BARS];
};

/* Init code. Returns a handle >= 0, or -ENOSPC / -EINVAL after a message. A card
 * with BAR 0 only, subsystem IDs 0, ops readl/writel: */
int rtapi_pcisim_register(unsigned int vendor, unsigned int device, unsigned long bar_len,
			  const struct rtapi_pcisim_ops *ops, void *dev, const char *name);
/* A card with several BARs, ops read/write (the card description is copied): */
int rtapi_pcisim_register_card(const struct rtapi_pcisim_card *card,
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
/* The first free simulated card from handle 'from' on matching one of ids (claimed
 * for 'owner'): its handle with *which = the matching entry, or -ENODEV. */
int rtapi_pcisim_claim_match(const struct rtapi_pci_id *ids, int from, const char *owner,
			     int *which);
unsigned long rtapi_pcisim_bar_len(int handle, int bar);	/* 0: no such BAR */
const char *rtapi_pcisim_name(int handle);
void rtapi_pcisim_release(int handle);
rtapi_u32 rtapi_pcisim_read(int handle, int bar, unsigned long offset, int size);
void rtapi_pcisim_write(int handle, int bar, unsigned long offset, int size, rtapi_u32 value);

#ifdef __cplusplus
}
#endif
#endif /* RTAPI_PCI_H */
