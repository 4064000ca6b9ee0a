/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pcl720.c - Advantech PCL-720 digital I/O (pcl720(9), small-boards.md §2):
 * loadrt pcl720 ioaddr=0x200[,...] (up to 8 cards). Per card N: pins
 * pcl720.N.pin-MM-out (in), pin-MM-in / pin-MM-in-not (out), wait-clocks (u32 out),
 * params reset-time (ns, default 5000), pin-MM-reset, pin-MM-out-invert; functions
 * pcl720.N.read, .write, .reset (no FP). Registers base+0..3: inputs 0-31 on read,
 * outputs 0-31 on write, byte 0 first.
 * Two choices differ from the EMC2 driver: the four ports are claimed
 * (rtapi_request_region: the simulated flavor needs it for port access, and it keeps
 * two drivers off one card), and reset drives only the reset pins low, leaving every
 * other output as write() set it (the old code also dropped the other pins' inversion). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("Advantech PCL-720 digital I/O");

#define MAX_CARDS 8
static int ioaddr[MAX_CARDS];
RTAPI_MP_ARRAY_INT(ioaddr, MAX_CARDS, "base addresses of the cards");

struct pcl720 {			/* HAL memory, owned by the card's functions */
	hal_bit_t *out[32], *in[32], *in_not[32];
	hal_u32_t *wait_clocks;
	hal_u32_t reset_time;	/* ns after write(), clamped to period/4 */
	hal_bit_t reset[32], invert[32];
	unsigned int base;
	rtapi_u32 written;	/* last word on the outputs */
	long long write_time;	/* rtapi_get_time() of the last write */
	int claimed;
};

static int comp_id;
static struct pcl720 *cards;
static int num_cards;

static void pcl720_read(void *arg, long period)
{
	struct pcl720 *c = arg;
	rtapi_u32 w = 0;
	int i;

	for (i = 0; i < 4; i++)
		w |= (rtapi_u32)rtapi_inb(c->base + i) << (8 * i);
	for (i = 0; i < 32; i++) {
		*c->in[i] = (w >> i) & 1;
		*c->in_not[i] = !*c->in[i];
	}
}

static void put_word(struct pcl720 *c, rtapi_u32 w)
{
	int i;

	for (i = 0; i < 4; i++)
		rtapi_outb((w >> (8 * i)) & 0xff, c->base + i);
	c->written = w;
}

static void pcl720_write(void *arg, long period)
{
	struct pcl720 *c = arg;
	rtapi_u32 w = 0;
	int i;

	for (i = 0; i < 32; i++)
		w |= (rtapi_u32)((*c->out[i] ^ c->invert[i]) & 1) << i;
	put_word(c, w);
	c->write_time = rtapi_get_time();
}

static void pcl720_reset(void *arg, long period)
{
	struct pcl720 *c = arg;
	rtapi_u32 mask = 0, w;
	long long deadline, t0;
	int i;

	for (i = 0; i < 32; i++)
		mask |= (rtapi_u32)(c->reset[i] & 1) << i;
	w = c->written & ~mask;
	if (!mask || w == c->written)
		return;
	if (c->reset_time > period / 4)
		c->reset_time = period / 4;
	deadline = c->write_time + c->reset_time;
	t0 = rtapi_get_clocks();
	while (rtapi_get_time() < deadline)
		;
	*c->wait_clocks = (rtapi_u32)(rtapi_get_clocks() - t0);
	put_word(c, w);
}

static int export_card(struct pcl720 *c, int n)
{
	char fn[HAL_NAME_LEN + 1];
	int i, err = 0;

	for (i = 0; !err && i < 32; i++) {
		err = hal_pin_bit_newf(HAL_IN, &c->out[i], comp_id, "pcl720.%d.pin-%02d-out", n, i);
		if (!err)
			err = hal_pin_bit_newf(HAL_OUT, &c->in[i], comp_id, "pcl720.%d.pin-%02d-in", n, i);
		if (!err)
			err = hal_pin_bit_newf(HAL_OUT, &c->in_not[i], comp_id,
					       "pcl720.%d.pin-%02d-in-not", n, i);
		if (!err)
			err = hal_param_bit_newf(HAL_RW, &c->reset[i], comp_id,
						 "pcl720.%d.pin-%02d-reset", n, i);
		if (!err)
			err = hal_param_bit_newf(HAL_RW, &c->invert[i], comp_id,
						 "pcl720.%d.pin-%02d-out-invert", n, i);
	}
	if (!err)
		err = hal_pin_u32_newf(HAL_OUT, &c->wait_clocks, comp_id, "pcl720.%d.wait-clocks", n);
	if (!err)
		err = hal_param_u32_newf(HAL_RW, &c->reset_time, comp_id, "pcl720.%d.reset-time", n);
	if (err)
		return err;
	c->reset_time = 5000;
	rtapi_snprintf(fn, sizeof(fn), "pcl720.%d.read", n);
	err = hal_export_funct(fn, pcl720_read, c, 0, 0, comp_id);
	rtapi_snprintf(fn, sizeof(fn), "pcl720.%d.write", n);
	if (!err)
		err = hal_export_funct(fn, pcl720_write, c, 0, 0, comp_id);
	rtapi_snprintf(fn, sizeof(fn), "pcl720.%d.reset", n);
	if (!err)
		err = hal_export_funct(fn, pcl720_reset, c, 0, 0, comp_id);
	return err;
}

static void release_all(void)
{
	int n;

	for (n = 0; n < num_cards; n++)
		if (cards[n].claimed)
			rtapi_release_region(cards[n].base, 4);
}

int rtapi_app_main(void)
{
	int n, num, err = 0;

	for (num = 0; num < MAX_CARDS && ioaddr[num] > 0; num++)
		if (ioaddr[num] > 0xfffc) {
			rtapi_print_msg(RTAPI_MSG_ERR, "pcl720: ioaddr=0x%x is not an I/O port "
					"address (at most 0xfffc)\n", ioaddr[num]);
			return -EINVAL;
		}
	if (num == 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pcl720: give the cards' base addresses: "
				"ioaddr=0x200[,...]\n");
		return -EINVAL;
	}
	comp_id = hal_init("pcl720");
	if (comp_id < 0)
		return comp_id;
	cards = hal_malloc(num * (long)sizeof(*cards));
	if (!cards) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pcl720: out of HAL memory\n");
		hal_exit(comp_id);
		return -ENOMEM;
	}
	num_cards = num;
	for (n = 0; n < num; n++) {
		cards[n].base = ioaddr[n];
		cards[n].claimed = 0;
	}
	for (n = 0; !err && n < num; n++) {
		cards[n].claimed = rtapi_request_region(ioaddr[n], 4, "pcl720") != 0;
		if (!cards[n].claimed) {
			rtapi_print_msg(RTAPI_MSG_ERR, "pcl720: card %d: ports 0x%x-0x%x are busy or "
					"not accessible\n", n, ioaddr[n], ioaddr[n] + 3);
			err = -EBUSY;
		}
		if (!err)
			err = export_card(&cards[n], n);
	}
	if (err) {
		release_all();
		hal_exit(comp_id);
		return err;
	}
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	release_all();
	hal_exit(comp_id);
}
