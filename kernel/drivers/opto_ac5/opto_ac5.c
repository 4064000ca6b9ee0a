/* SPDX-License-Identifier: GPL-2.0-or-later */
/* opto_ac5.c - Opto22 PCI-AC5 digital I/O (opto_ac5(9), small-boards.md §1):
 * loadrt opto_ac5 [portconfig0=0xN] [portconfig1=0xN]; up to 4 boards in PCI order,
 * each port configured the same way (bit n = 1: point n is an output; default
 * 0xfff000, points 0-11 inputs). Per board B, port P: pins
 * opto_ac5.B.portP.in-NN / -not (inputs), .out-NN and param .out-NN-invert (outputs),
 * opto_ac5.B.led0..3; functions opto_ac5.B.digital-read / digital-write (no FP).
 * The card is active low: a data bit of 0 means the point is on. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_pci.h"
#include "hal.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("Opto22 PCI-AC5 digital I/O");

static int portconfig0 = 0xfff000;
RTAPI_MP_INT(portconfig0, "port 0 directions, bit n = 1: point n is an output");
static int portconfig1 = 0xfff000;
RTAPI_MP_INT(portconfig1, "port 1 directions, bit n = 1: point n is an output");

#define AC5_VENDOR 0x148a
#define AC5_DEVICE 0xac05
#define MAX_BOARDS 4
#define POINTS 24
#define LED_BITS 0xc0000000u	/* bits 31, 30: the port's two LEDs, 1 = off */
#define ALL_OFF 0xc0ffffffu

static const unsigned long cfg_reg[2] = { 0x004, 0x014 };
static const unsigned long out_reg[2] = { 0x008, 0x018 };
static const unsigned long in_reg[2] = { 0x300, 0x700 };

struct ac5_port {		/* HAL memory, owned by the board's functions */
	hal_bit_t *in[POINTS], *in_not[POINTS];
	hal_bit_t *out[POINTS];
	hal_bit_t invert[POINTS];
	hal_bit_t *led[2];	/* bit 31, bit 30 */
	rtapi_u32 outputs;	/* configuration: 1 = output */
};

struct ac5_board {
	struct ac5_port port[2];
	struct rtapi_pci_bar *bar;
};

static int comp_id;
static struct ac5_board *boards;
static int num_boards;

static void ac5_read(void *arg, long period)
{
	struct ac5_board *b = arg;
	int p, i;

	for (p = 0; p < 2; p++) {
		struct ac5_port *pt = &b->port[p];
		rtapi_u32 v = rtapi_pci_readl(b->bar, in_reg[p]);

		for (i = 0; i < POINTS; i++) {
			if (pt->outputs & (1u << i))
				continue;
			*pt->in[i] = !((v >> i) & 1);
			*pt->in_not[i] = !*pt->in[i];
		}
	}
}

static void ac5_write(void *arg, long period)
{
	struct ac5_board *b = arg;
	int p, i;

	for (p = 0; p < 2; p++) {
		struct ac5_port *pt = &b->port[p];
		rtapi_u32 v = 0;

		for (i = 0; i < POINTS; i++)
			if ((pt->outputs & (1u << i)) && !((*pt->out[i] ^ pt->invert[i]) & 1))
				v |= 1u << i;
		if (!*pt->led[0])
			v |= 1u << 31;
		if (!*pt->led[1])
			v |= 1u << 30;
		rtapi_pci_writel(b->bar, out_reg[p], v);
	}
}

static int export_port(struct ac5_port *pt, int bn, int p)
{
	int i, err = 0;

	for (i = 0; !err && i < POINTS; i++) {
		if (pt->outputs & (1u << i)) {
			err = hal_pin_bit_newf(HAL_IN, &pt->out[i], comp_id,
					       "opto_ac5.%d.port%d.out-%02d", bn, p, i);
			if (!err)
				err = hal_param_bit_newf(HAL_RW, &pt->invert[i], comp_id,
							 "opto_ac5.%d.port%d.out-%02d-invert", bn, p, i);
		} else {
			err = hal_pin_bit_newf(HAL_OUT, &pt->in[i], comp_id,
					       "opto_ac5.%d.port%d.in-%02d", bn, p, i);
			if (!err)
				err = hal_pin_bit_newf(HAL_OUT, &pt->in_not[i], comp_id,
						       "opto_ac5.%d.port%d.in-%02d-not", bn, p, i);
		}
	}
	/* The page lists the LED pins as OUT, but an OUT pin cannot be set or driven by
	 * a signal, so the LEDs could never be lit: they are inputs of digital-write. */
	for (i = 0; !err && i < 2; i++)
		err = hal_pin_bit_newf(HAL_IN, &pt->led[i], comp_id, "opto_ac5.%d.led%d",
				       bn, 2 * p + i);
	return err;
}

static int export_board(struct ac5_board *b, int bn)
{
	char fn[HAL_NAME_LEN + 1];
	int p, err = 0;

	for (p = 0; !err && p < 2; p++) {
		b->port[p].outputs = (rtapi_u32)(p ? portconfig1 : portconfig0) & 0xffffffu;
		err = export_port(&b->port[p], bn, p);
	}
	if (err)
		return err;
	for (p = 0; p < 2; p++)
		rtapi_pci_writel(b->bar, cfg_reg[p], b->port[p].outputs | LED_BITS);
	rtapi_snprintf(fn, sizeof(fn), "opto_ac5.%d.digital-read", bn);
	err = hal_export_funct(fn, ac5_read, b, 0, 0, comp_id);
	rtapi_snprintf(fn, sizeof(fn), "opto_ac5.%d.digital-write", bn);
	if (!err)
		err = hal_export_funct(fn, ac5_write, b, 0, 0, comp_id);
	return err;
}

/* Every output and LED off, and the BARs given back. */
static void release_boards(void)
{
	int n;

	for (n = 0; n < num_boards; n++) {
		rtapi_pci_writel(boards[n].bar, out_reg[0], ALL_OFF);
		rtapi_pci_writel(boards[n].bar, out_reg[1], ALL_OFF);
		rtapi_pci_unmap_bar(boards[n].bar);
	}
	num_boards = 0;
}

int rtapi_app_main(void)
{
	struct rtapi_pci_bar *bar[MAX_BOARDS];
	int n, num, err = 0;

	if ((portconfig0 & ~0xc0ffffff) || (portconfig1 & ~0xc0ffffff)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "opto_ac5: portconfig0=0x%x portconfig1=0x%x: only "
				"bits 0-23 (points) and 30-31 (LEDs) exist\n", portconfig0, portconfig1);
		return -EINVAL;
	}
	for (num = 0; num < MAX_BOARDS; num++) {
		err = rtapi_pci_map_bar(AC5_VENDOR, AC5_DEVICE, num, 0, "opto_ac5", &bar[num]);
		if (err)
			break;
	}
	if (err == -ENODEV)
		err = 0;
	if (!err && num == 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "opto_ac5: no PCI-AC5 board (PCI %04x:%04x) found\n",
				AC5_VENDOR, AC5_DEVICE);
		err = -ENODEV;
	}
	if (!err) {
		comp_id = hal_init("opto_ac5");
		err = comp_id < 0 ? comp_id : 0;
	}
	if (!err) {
		boards = hal_malloc(num * (long)sizeof(*boards));
		if (!boards) {
			rtapi_print_msg(RTAPI_MSG_ERR, "opto_ac5: out of HAL memory\n");
			hal_exit(comp_id);
			err = -ENOMEM;
		}
	}
	if (err) {
		while (num-- > 0)
			rtapi_pci_unmap_bar(bar[num]);
		return err;
	}
	for (n = 0; n < num; n++)
		boards[n].bar = bar[n];
	num_boards = num;
	for (n = 0; !err && n < num; n++)
		err = export_board(&boards[n], n);
	if (err) {
		release_boards();
		hal_exit(comp_id);
		return err;
	}
	rtapi_print_msg(RTAPI_MSG_INFO, "opto_ac5: %d board(s)\n", num);
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	release_boards();
	hal_exit(comp_id);
}
