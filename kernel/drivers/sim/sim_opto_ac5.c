/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sim_opto_ac5.c - simulated Opto22 PCI-AC5 boards (small-boards.md §1.2), found by
 * opto_ac5 before any real one: loadrt sim_opto_ac5 [count=N] (1..4). Per board B,
 * port P (TRUE = the point is on):
 *   sim-opto-ac5.B.portP.in-NN (bit IN) turns input point NN on;
 *   sim-opto-ac5.B.portP.out-NN (bit OUT) output point NN is on;
 *   sim-opto-ac5.B.portP.led0 / led1 (bit OUT) the LEDs of bits 31 / 30 are lit;
 *   sim-opto-ac5.B.portP.config / data (u32 OUT) the words last written;
 *   sim-opto-ac5.B.portP.reads / writes (u32 OUT) count data accesses. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_pci.h"
#include "hal.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("simulated Opto22 PCI-AC5");

static int count = 1;
RTAPI_MP_INT(count, "number of simulated boards, 1..4");

#define POINTS 24

struct sim_port {
	hal_bit_t *in[POINTS], *out[POINTS], *led[2];
	hal_u32_t *config, *data, *reads, *writes;
};

struct sim_board {		/* HAL memory; touched only by BAR accesses */
	struct sim_port port[2];
	int handle;
	char name[24];
};

static int comp_id;
static struct sim_board *boards;
static int num_boards;

static void show_outputs(struct sim_port *p)
{
	int i;

	for (i = 0; i < POINTS; i++)	/* on = configured output with its bit 0 */
		*p->out[i] = ((*p->config >> i) & 1) && !((*p->data >> i) & 1);
	*p->led[0] = ((*p->config >> 31) & 1) && !((*p->data >> 31) & 1);
	*p->led[1] = ((*p->config >> 30) & 1) && !((*p->data >> 30) & 1);
}

static rtapi_u32 board_readl(void *dev, unsigned long off)
{
	struct sim_board *b = dev;
	int p = off == 0x700 || off == 0x500 || off == 0x014 || off == 0x018;
	struct sim_port *pt = &b->port[p];
	rtapi_u32 v = 0;
	int i;

	if (off == 0x100 || off == 0x500)
		return *pt->config;
	if (off != 0x300 && off != 0x700)
		return 0;
	++*pt->reads;
	for (i = 0; i < POINTS; i++)	/* active low; outputs read back their latch */
		if (((*pt->config >> i) & 1) ? (*pt->data >> i) & 1 : !*pt->in[i])
			v |= 1u << i;
	return v;
}

static void board_writel(void *dev, unsigned long off, rtapi_u32 v)
{
	struct sim_board *b = dev;
	struct sim_port *pt = &b->port[off >= 0x010];

	if (off == 0x004 || off == 0x014) {
		*pt->config = v;
	} else if (off == 0x008 || off == 0x018) {
		++*pt->writes;
		*pt->data = v;
	} else {
		return;
	}
	show_outputs(pt);
}

static const struct rtapi_pcisim_ops board_ops = { .readl = board_readl, .writel = board_writel };

static int export_board(struct sim_board *b, int bn)
{
	int p, i, err = 0;

	for (p = 0; !err && p < 2; p++) {
		struct sim_port *pt = &b->port[p];

		for (i = 0; !err && i < POINTS; i++) {
			err = hal_pin_bit_newf(HAL_IN, &pt->in[i], comp_id,
					       "sim-opto-ac5.%d.port%d.in-%02d", bn, p, i);
			if (!err)
				err = hal_pin_bit_newf(HAL_OUT, &pt->out[i], comp_id,
						       "sim-opto-ac5.%d.port%d.out-%02d", bn, p, i);
		}
		for (i = 0; !err && i < 2; i++)
			err = hal_pin_bit_newf(HAL_OUT, &pt->led[i], comp_id,
					       "sim-opto-ac5.%d.port%d.led%d", bn, p, i);
		if (!err)
			err = hal_pin_u32_newf(HAL_OUT, &pt->config, comp_id, "sim-opto-ac5.%d.port%d.config", bn, p);
		if (!err)
			err = hal_pin_u32_newf(HAL_OUT, &pt->data, comp_id, "sim-opto-ac5.%d.port%d.data", bn, p);
		if (!err)
			err = hal_pin_u32_newf(HAL_OUT, &pt->reads, comp_id, "sim-opto-ac5.%d.port%d.reads", bn, p);
		if (!err)
			err = hal_pin_u32_newf(HAL_OUT, &pt->writes, comp_id, "sim-opto-ac5.%d.port%d.writes", bn, p);
	}
	return err;
}

static void unregister_all(void)
{
	int n;

	for (n = 0; n < num_boards; n++)
		if (boards[n].handle >= 0)
			rtapi_pcisim_unregister(boards[n].handle);
}

int rtapi_app_main(void)
{
	int n, err = 0;

	if (count < 1 || count > 4) {
		rtapi_print_msg(RTAPI_MSG_ERR, "sim_opto_ac5: count=%d, must be 1..4\n", count);
		return -EINVAL;
	}
	comp_id = hal_init("sim_opto_ac5");
	if (comp_id < 0)
		return comp_id;
	boards = hal_malloc(count * (long)sizeof(*boards));
	if (!boards) {
		rtapi_print_msg(RTAPI_MSG_ERR, "sim_opto_ac5: out of HAL memory\n");
		hal_exit(comp_id);
		return -ENOMEM;
	}
	for (n = 0; n < count; n++)
		boards[n].handle = -1;
	num_boards = count;
	for (n = 0; !err && n < count; n++) {
		rtapi_snprintf(boards[n].name, sizeof(boards[n].name), "sim-opto-ac5.%d", n);
		err = export_board(&boards[n], n);
		if (!err) {
			boards[n].handle = rtapi_pcisim_register(0x148a, 0xac05, 0x1000, &board_ops,
								 &boards[n], boards[n].name);
			err = boards[n].handle < 0 ? boards[n].handle : 0;
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
