/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_pcisim.c - the table of simulated PCI cards (rtapi_pci.h), one file for both
 * flavors, locked as rtapi_iosim.c is: realtime accessors count themselves in
 * 'users' and take no lock; init code serialises on 'table_lock'. */
#include "rtapi.h"
#include "rtapi_pci.h"
#include "rtapi_string.h"

enum { CARD_FREE = 0, CARD_ACTIVE, CARD_ORPHAN };

struct pcisim_card {
	int state, users;
	struct rtapi_pcisim_card card;	/* IDs and BAR lengths */
	int multi;			/* registered with ..._card: ops read/write */
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

/* one slot filled under the lock; 'multi' says which ops the card uses */
static int add_card(const struct rtapi_pcisim_card *card, int multi,
		    const struct rtapi_pcisim_ops *ops, void *dev, const char *name)
{
	int i;

	lock_table();
	for (i = 0; i < RTAPI_PCISIM_MAX && cards[i].state != CARD_FREE; i++)
		;
	if (i == RTAPI_PCISIM_MAX) {
		rtapi_mutex_give(&table_lock);
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: simulated PCI card '%s': all %d slots in use\n",
				name, RTAPI_PCISIM_MAX);
		return -ENOSPC;
	}
	cards[i].card = *card;
	cards[i].multi = multi;
	cards[i].ops = ops;
	cards[i].dev = dev;
	cards[i].name = name;
	cards[i].owner = 0;
	__atomic_store_n(&cards[i].state, CARD_ACTIVE, __ATOMIC_RELEASE);
	rtapi_mutex_give(&table_lock);
	return i;
}

int rtapi_pcisim_register(unsigned int vendor, unsigned int device, unsigned long bar_len,
			  const struct rtapi_pcisim_ops *ops, void *dev, const char *name)
{
	struct rtapi_pcisim_card card;

	if (!bar_len || !ops || !ops->readl || !ops->writel) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: simulated PCI card '%s': bad BAR or ops\n", name);
		return -EINVAL;
	}
	memset(&card, 0, sizeof(card));
	card.id.vendor = vendor;
	card.id.device = device;
	card.bar_len[0] = bar_len;
	return add_card(&card, 0, ops, dev, name);
}

int rtapi_pcisim_register_card(const struct rtapi_pcisim_card *card,
			       const struct rtapi_pcisim_ops *ops, void *dev, const char *name)
{
	if (!card || !card->id.vendor || !ops || !ops->read || !ops->write) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: simulated PCI card '%s': bad IDs or ops\n", name);
		return -EINVAL;
	}
	return add_card(card, 1, ops, dev, name);
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

		if (c->state != CARD_ACTIVE || c->card.id.vendor != vendor ||
		    c->card.id.device != device)
			continue;
		if (seen++ != index)
			continue;
		if (c->owner) {
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: simulated PCI card '%s' is in use by "
					"'%s'\n", c->name, c->owner);
			rc = -EBUSY;
		} else {
			c->owner = owner;
			*len = c->card.bar_len[0];
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

static int id_match(const struct rtapi_pci_id *a, const struct rtapi_pci_id *b)
{
	return a->vendor == b->vendor && a->device == b->device && a->subvendor == b->subvendor &&
	       a->subdevice == b->subdevice;
}

int rtapi_pcisim_claim_match(const struct rtapi_pci_id *ids, int from, const char *owner,
			     int *which)
{
	int i, k, rc = -ENODEV;

	lock_table();
	for (i = from < 0 ? 0 : from; i < RTAPI_PCISIM_MAX && rc < 0; i++) {
		struct pcisim_card *c = &cards[i];

		if (c->state != CARD_ACTIVE || c->owner)
			continue;
		for (k = 0; ids[k].vendor; k++)
			if (id_match(&ids[k], &c->card.id)) {
				c->owner = owner;
				*which = k;
				rc = i;
				break;
			}
	}
	rtapi_mutex_give(&table_lock);
	return rc;
}

unsigned long rtapi_pcisim_bar_len(int handle, int bar)
{
	return bar >= 0 && bar < RTAPI_PCI_BARS ? cards[handle].card.bar_len[bar] : 0;
}

const char *rtapi_pcisim_name(int handle)
{
	return cards[handle].name;
}

/* Accessors count themselves in 'users' so that unregister can wait them out. */
rtapi_u32 rtapi_pcisim_read(int handle, int bar, unsigned long offset, int size)
{
	struct pcisim_card *c = &cards[handle];
	rtapi_u32 v = size == 1 ? 0xff : ~0u;

	__atomic_add_fetch(&c->users, 1, __ATOMIC_ACQ_REL);
	if (__atomic_load_n(&c->state, __ATOMIC_ACQUIRE) == CARD_ACTIVE &&
	    offset + size <= rtapi_pcisim_bar_len(handle, bar)) {
		if (c->multi)
			v = c->ops->read(c->dev, bar, offset, size);
		else if (size == 4)
			v = c->ops->readl(c->dev, offset);
	}
	__atomic_sub_fetch(&c->users, 1, __ATOMIC_RELEASE);
	return v;
}

void rtapi_pcisim_write(int handle, int bar, unsigned long offset, int size, rtapi_u32 value)
{
	struct pcisim_card *c = &cards[handle];

	__atomic_add_fetch(&c->users, 1, __ATOMIC_ACQ_REL);
	if (__atomic_load_n(&c->state, __ATOMIC_ACQUIRE) == CARD_ACTIVE &&
	    offset + size <= rtapi_pcisim_bar_len(handle, bar)) {
		if (c->multi)
			c->ops->write(c->dev, bar, offset, size, value);
		else if (size == 4)
			c->ops->writel(c->dev, offset, value);
	}
	__atomic_sub_fetch(&c->users, 1, __ATOMIC_RELEASE);
}
