/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sim_pcl720.c - a simulated Advantech PCL-720 (small-boards.md §2.1) behind
 * io..io+3 (rtapi_iosim.h): loadrt sim_pcl720 io=0x200[,...]. Per card N:
 *   sim-pcl720.N.in-MM (bit IN) what the outside drives on input MM;
 *   sim-pcl720.N.out-MM (bit OUT) the output latch MM;
 *   sim-pcl720.N.out (u32 OUT) the output word; out-writes / in-reads (u32 OUT)
 *     count byte accesses. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_iosim.h"
#include "hal.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("simulated Advantech PCL-720");

#define SIM_MAX 8
static int io[SIM_MAX];
RTAPI_MP_ARRAY_INT(io, SIM_MAX, "base addresses of the simulated cards");

struct sim_card {		/* HAL memory; touched only by port accesses */
	hal_bit_t *in[32], *out[32];
	hal_u32_t *word, *writes, *reads;
	int handle;
	char name[24];
};

static int comp_id;
static struct sim_card *cards;
static int num_cards;

static unsigned char card_inb(void *dev, unsigned int off)
{
	struct sim_card *c = dev;
	unsigned char b = 0;
	int i;

	++*c->reads;
	for (i = 0; i < 8; i++)
		b |= (unsigned char)(*c->in[8 * off + i] & 1) << i;
	return b;
}

static void card_outb(void *dev, unsigned int off, unsigned char b)
{
	struct sim_card *c = dev;
	int i;

	++*c->writes;
	*c->word = (*c->word & ~(0xffu << (8 * off))) | (rtapi_u32)b << (8 * off);
	for (i = 0; i < 8; i++)
		*c->out[8 * off + i] = (b >> i) & 1;
}

static const struct rtapi_iosim_ops card_ops = { card_inb, card_outb };

static int export_card(struct sim_card *c, int n)
{
	int i, err = 0;

	for (i = 0; !err && i < 32; i++) {
		err = hal_pin_bit_newf(HAL_IN, &c->in[i], comp_id, "sim-pcl720.%d.in-%02d", n, i);
		if (!err)
			err = hal_pin_bit_newf(HAL_OUT, &c->out[i], comp_id, "sim-pcl720.%d.out-%02d", n, i);
	}
	if (!err)
		err = hal_pin_u32_newf(HAL_OUT, &c->word, comp_id, "sim-pcl720.%d.out", n);
	if (!err)
		err = hal_pin_u32_newf(HAL_OUT, &c->writes, comp_id, "sim-pcl720.%d.out-writes", n);
	if (!err)
		err = hal_pin_u32_newf(HAL_OUT, &c->reads, comp_id, "sim-pcl720.%d.in-reads", n);
	return err;
}

static void unregister_all(void)
{
	int n;

	for (n = 0; n < num_cards; n++)
		if (cards[n].handle >= 0)
			rtapi_iosim_unregister(cards[n].handle);
}

int rtapi_app_main(void)
{
	int n, num, err = 0;

	for (num = 0; num < SIM_MAX && io[num] > 0; num++)
		if (io[num] > 0xfffc) {
			rtapi_print_msg(RTAPI_MSG_ERR, "sim_pcl720: io=0x%x: at most 0xfffc\n", io[num]);
			return -EINVAL;
		}
	if (num == 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "sim_pcl720: give the cards' addresses: io=0x...\n");
		return -EINVAL;
	}
	comp_id = hal_init("sim_pcl720");
	if (comp_id < 0)
		return comp_id;
	cards = hal_malloc(num * (long)sizeof(*cards));
	if (!cards) {
		rtapi_print_msg(RTAPI_MSG_ERR, "sim_pcl720: out of HAL memory\n");
		hal_exit(comp_id);
		return -ENOMEM;
	}
	for (n = 0; n < num; n++)
		cards[n].handle = -1;
	num_cards = num;
	for (n = 0; !err && n < num; n++) {
		rtapi_snprintf(cards[n].name, sizeof(cards[n].name), "sim-pcl720.%d", n);
		err = export_card(&cards[n], n);
		if (!err) {
			cards[n].handle = rtapi_iosim_register(io[n], 4, &card_ops, &cards[n],
							       cards[n].name);
			err = cards[n].handle < 0 ? cards[n].handle : 0;
		}
	}
	if (err) {
		unregister_all();
		hal_exit(comp_id);
		return err;
	}
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	unregister_all();
	hal_exit(comp_id);
}
