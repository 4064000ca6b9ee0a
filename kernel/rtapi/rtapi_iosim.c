/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_iosim.c - the table of simulated port ranges (rtapi_iosim.h), one file for
 * both flavors. Realtime accessors take no lock: a slot is published with a release
 * store of its state, and an access counts itself in 'users' so that unregistering
 * can wait until no callback runs. Registration and claims (init code) serialise on
 * 'table_lock', which realtime code never touches. */
#include "rtapi.h"
#include "rtapi_iosim.h"

enum slot_state {
	SLOT_FREE = 0,
	SLOT_ACTIVE,		/* callbacks are called */
	SLOT_ORPHAN,		/* device gone, a driver's claim remains: reads 0xff */
};

struct iosim_slot {
	int state;		/* enum slot_state, read by accessors with acquire */
	int users;		/* accessors inside a callback right now */
	unsigned int base, size;
	const struct rtapi_iosim_ops *ops;
	void *dev;
	const char *name;	/* the device's */
	char claim[RTAPI_NAME_LEN + 1];	/* the claiming driver's, "" when unclaimed */
	unsigned long claim_base, claim_size;
};

static struct iosim_slot slots[RTAPI_IOSIM_MAX];
static int nr_slots;		/* highest used index + 1: accessors stop there */
static unsigned long table_lock;

static void lock_table(void)
{
	while (rtapi_mutex_try(&table_lock))
		rtapi_sleep_ns(10000);
}

static int overlaps(unsigned long b1, unsigned long s1, unsigned long b2, unsigned long s2)
{
	return b1 < b2 + s2 && b2 < b1 + s1;
}

int rtapi_iosim_register(unsigned int base, unsigned int size,
			 const struct rtapi_iosim_ops *ops, void *dev, const char *name)
{
	int i, free_slot = -1;

	if (size == 0 || base + size < base || !ops || !ops->inb || !ops->outb) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: simulated device '%s': bad range 0x%x+%u\n",
				name, base, size);
		return -EINVAL;
	}
	lock_table();
	for (i = 0; i < RTAPI_IOSIM_MAX; i++) {
		struct iosim_slot *s = &slots[i];

		if (s->state == SLOT_FREE) {
			if (free_slot < 0)
				free_slot = i;
			continue;
		}
		if (overlaps(base, size, s->base, s->size)) {
			rtapi_mutex_give(&table_lock);
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: simulated device '%s' at 0x%x+%u "
					"overlaps '%s' at 0x%x+%u\n", name, base, size,
					s->name, s->base, s->size);
			return -EBUSY;
		}
	}
	if (free_slot < 0) {
		rtapi_mutex_give(&table_lock);
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: simulated device '%s': all %d port ranges "
				"in use\n", name, RTAPI_IOSIM_MAX);
		return -ENOSPC;
	}
	slots[free_slot].base = base;
	slots[free_slot].size = size;
	slots[free_slot].ops = ops;
	slots[free_slot].dev = dev;
	slots[free_slot].name = name;
	slots[free_slot].claim[0] = 0;
	__atomic_store_n(&slots[free_slot].state, SLOT_ACTIVE, __ATOMIC_RELEASE);
	if (free_slot + 1 > nr_slots)
		__atomic_store_n(&nr_slots, free_slot + 1, __ATOMIC_RELEASE);
	rtapi_mutex_give(&table_lock);
	return free_slot;
}

void rtapi_iosim_unregister(int handle)
{
	struct iosim_slot *s;

	if (handle < 0 || handle >= RTAPI_IOSIM_MAX)
		return;
	s = &slots[handle];
	lock_table();
	if (s->state == SLOT_ACTIVE)
		__atomic_store_n(&s->state, s->claim[0] ? SLOT_ORPHAN : SLOT_FREE, __ATOMIC_RELEASE);
	rtapi_mutex_give(&table_lock);
	/* an access that saw ACTIVE before the store may still be in a callback */
	while (__atomic_load_n(&s->users, __ATOMIC_ACQUIRE))
		rtapi_sleep_ns(100000);
}

/* The slot holding 'port', with its user count raised, or NULL. */
static struct iosim_slot *enter(unsigned int port)
{
	int i, n = __atomic_load_n(&nr_slots, __ATOMIC_ACQUIRE);

	for (i = 0; i < n; i++) {
		struct iosim_slot *s = &slots[i];

		if (__atomic_load_n(&s->state, __ATOMIC_ACQUIRE) == SLOT_FREE)
			continue;
		if (port - s->base >= s->size)
			continue;
		__atomic_add_fetch(&s->users, 1, __ATOMIC_ACQ_REL);
		return s;
	}
	return 0;
}

static void leave(struct iosim_slot *s)
{
	__atomic_sub_fetch(&s->users, 1, __ATOMIC_RELEASE);
}

int rtapi_iosim_inb(unsigned int port, unsigned char *byte)
{
	struct iosim_slot *s = enter(port);

	if (!s)
		return 0;
	if (__atomic_load_n(&s->state, __ATOMIC_ACQUIRE) == SLOT_ACTIVE)
		*byte = s->ops->inb(s->dev, port - s->base);
	else
		*byte = 0xff;	/* nothing drives the bus */
	leave(s);
	return 1;
}

int rtapi_iosim_outb(unsigned int port, unsigned char byte)
{
	struct iosim_slot *s = enter(port);

	if (!s)
		return 0;
	if (__atomic_load_n(&s->state, __ATOMIC_ACQUIRE) == SLOT_ACTIVE)
		s->ops->outb(s->dev, port - s->base, byte);
	leave(s);
	return 1;
}

int rtapi_iosim_claim(unsigned long base, unsigned long size, const char *name)
{
	int i, rc = 0;

	lock_table();
	for (i = 0; i < RTAPI_IOSIM_MAX; i++) {
		struct iosim_slot *s = &slots[i];

		if (s->state != SLOT_ACTIVE || !overlaps(base, size, s->base, s->size))
			continue;
		if (base < s->base || base + size > s->base + s->size) {
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: region 0x%lx+%lu for '%s' straddles "
					"simulated device '%s' at 0x%x+%u\n", base, size, name,
					s->name, s->base, s->size);
			rc = -EBUSY;
		} else if (s->claim[0]) {
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: region 0x%lx+%lu for '%s' refused: "
					"simulated device '%s' is in use by '%s'\n", base, size,
					name, s->name, s->claim);
			rc = -EBUSY;
		} else {
			rtapi_snprintf(s->claim, sizeof(s->claim), "%s", name && *name ? name : "?");
			s->claim_base = base;
			s->claim_size = size;
			rc = 1;
		}
		break;
	}
	rtapi_mutex_give(&table_lock);
	return rc;
}

int rtapi_iosim_release(unsigned long base, unsigned long size)
{
	int i, rc = 0;

	lock_table();
	for (i = 0; i < RTAPI_IOSIM_MAX; i++) {
		struct iosim_slot *s = &slots[i];

		if (s->state == SLOT_FREE || !s->claim[0] || s->claim_base != base ||
		    s->claim_size != size)
			continue;
		s->claim[0] = 0;
		if (s->state == SLOT_ORPHAN)
			__atomic_store_n(&s->state, SLOT_FREE, __ATOMIC_RELEASE);
		rc = 1;
		break;
	}
	rtapi_mutex_give(&table_lock);
	return rc;
}
