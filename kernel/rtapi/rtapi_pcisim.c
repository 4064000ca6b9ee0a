/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_pcisim.c - the table of simulated PCI cards (rtapi_pci.h), one file for both
 * flavors, locked as rtapi_iosim.c is: realtime accessors count themselves in
 * 'users' and take no lock; init code serialises on 'table_lock'. */
#include "rtapi.h"
#include "rtapi_pci.h"

enum { CARD_FREE = 0, CARD_ACTIVE, CARD_ORPHAN };

struct pcisim_card {
	int state, users;
	unsigned int vendor, device;
	unsigned long len;
	const struct rtapi_pcisim_ops *ops;
	void *dev;
	const char *name;
	const char *owner;	/* the mapping driver's, NULL when unmapped */
};

static struct pcisim_card cards[RTAPI_PCISIM_MAX];
static unsigned long table_lock;

static void lock_table(void)
{
	while (rtapi_mutex_try(&table_lock))
		rtapi_sleep_ns(10000);
}

int rtapi_pcisim_register(unsigned int vendor, unsigned int device, unsigned long bar_len,
			  const struct rtapi_pcisim_ops *ops, void *dev, const char *name)
{
	int i;

	if (!bar_len || !ops || !ops->readl || !ops->writel) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: simulated PCI card '%s': bad BAR or ops\n", name);
		return -EINVAL;
	}
	lock_table();
	for (i = 0; i < RTAPI_PCISIM_MAX && cards[i].state != CARD_FREE; i++)
		;
	if (i == RTAPI_PCISIM_MAX) {
		rtapi_mutex_give(&table_lock);
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: simulated PCI card '%s': all %d slots in use\n",
				name, RTAPI_PCISIM_MAX);
		return -ENOSPC;
	}
	cards[i].vendor = vendor;
	cards[i].device = device;
	cards[i].len = bar_len;
	cards[i].ops = ops;
	cards[i].dev = dev;
	cards[i].name = name;
	cards[i].owner = 0;
	__atomic_store_n(&cards[i].state, CARD_ACTIVE, __ATOMIC_RELEASE);
	rtapi_mutex_give(&table_lock);
	return i;
}

void rtapi_pcisim_unregister(int handle)
{
	struct pcisim_card *c;

	if (handle < 0 || handle >= RTAPI_PCISIM_MAX)
		return;
	c = &cards[handle];
	lock_table();
	if (c->state == CARD_ACTIVE)
		__atomic_store_n(&c->state, c->owner ? CARD_ORPHAN : CARD_FREE, __ATOMIC_RELEASE);
	rtapi_mutex_give(&table_lock);
	while (__atomic_load_n(&c->users, __ATOMIC_ACQUIRE))
		rtapi_sleep_ns(100000);
}

int rtapi_pcisim_claim(unsigned int vendor, unsigned int device, int index,
		       const char *owner, int *skipped, unsigned long *len)
{
	int i, seen = 0, rc = -ENODEV;

	lock_table();
	for (i = 0; i < RTAPI_PCISIM_MAX; i++) {
		struct pcisim_card *c = &cards[i];

		if (c->state != CARD_ACTIVE || c->vendor != vendor || c->device != device)
			continue;
		if (seen++ != index)
			continue;
		if (c->owner) {
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: simulated PCI card '%s' is in use by "
					"'%s'\n", c->name, c->owner);
			rc = -EBUSY;
		} else {
			c->owner = owner;
			*len = c->len;
			rc = i;
		}
		break;
	}
	rtapi_mutex_give(&table_lock);
	*skipped = seen;
	return rc;
}

void rtapi_pcisim_release(int handle)
{
	struct pcisim_card *c = &cards[handle];

	lock_table();
	c->owner = 0;
	if (c->state == CARD_ORPHAN)
		__atomic_store_n(&c->state, CARD_FREE, __ATOMIC_RELEASE);
	rtapi_mutex_give(&table_lock);
}

rtapi_u32 rtapi_pcisim_readl(int handle, unsigned long offset)
{
	struct pcisim_card *c = &cards[handle];
	rtapi_u32 v = ~0u;

	__atomic_add_fetch(&c->users, 1, __ATOMIC_ACQ_REL);
	if (__atomic_load_n(&c->state, __ATOMIC_ACQUIRE) == CARD_ACTIVE && offset + 4 <= c->len)
		v = c->ops->readl(c->dev, offset);
	__atomic_sub_fetch(&c->users, 1, __ATOMIC_RELEASE);
	return v;
}

void rtapi_pcisim_writel(int handle, unsigned long offset, rtapi_u32 value)
{
	struct pcisim_card *c = &cards[handle];

	__atomic_add_fetch(&c->users, 1, __ATOMIC_ACQ_REL);
	if (__atomic_load_n(&c->state, __ATOMIC_ACQUIRE) == CARD_ACTIVE && offset + 4 <= c->len)
		c->ops->writel(c->dev, offset, value);
	__atomic_sub_fetch(&c->users, 1, __ATOMIC_RELEASE);
}
