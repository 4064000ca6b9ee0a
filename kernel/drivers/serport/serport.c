/* SPDX-License-Identifier: GPL-2.0-or-later */
/* serport.c - the modem-control bits of 8250/16550 serial ports as digital I/O
 * (serport(9), small-boards.md §4): loadrt serport io=0x3f8[,...] (up to 8). Per
 * port N: pins serport.N.pin-{1,6,8,9}-in and -in-not (DCD, DSR, CTS, RI), pins
 * serport.N.pin-{3,4,7}-out (TX via Break, DTR, RTS), params pin-{3,4,7}-out-invert
 * and ioaddr (RO); functions serport.N.read, serport.N.write (no FP). The port is
 * unusable as a UART while loaded: write() forces LCR and MCR every call. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("serial port modem-control bits as digital I/O");

#define MAX_PORTS 8
static int io[MAX_PORTS];
RTAPI_MP_ARRAY_INT(io, MAX_PORTS, "I/O addresses of the serial ports");

#define UART_LCR 3
#define UART_MCR 4
#define UART_MSR 6
#define LCR_BREAK 0x40
#define MCR_DTR 0x01
#define MCR_RTS 0x02

/* DB9 input pins and their MSR bits: DCD 7, DSR 5, CTS 4, RI 6. */
static const int in_pin[4] = { 1, 6, 8, 9 };
static const int in_bit[4] = { 7, 5, 4, 6 };
static const int out_pin[3] = { 3, 4, 7 };	/* TXD (Break), DTR, RTS */

struct serport {		/* HAL memory, owned by the port's functions */
	hal_bit_t *in[4], *in_not[4];
	hal_bit_t *out[3];
	hal_bit_t invert[3];
	hal_u32_t ioaddr;	/* RO param */
	int claimed;
};

static int comp_id;
static struct serport *ports;
static int num_ports;

static void serport_read(void *arg, long period)
{
	struct serport *p = arg;
	unsigned char msr = rtapi_inb(p->ioaddr + UART_MSR);
	int i;

	for (i = 0; i < 4; i++) {	/* an asserted (positive) line reads FALSE */
		*p->in[i] = !((msr >> in_bit[i]) & 1);
		*p->in_not[i] = !*p->in[i];
	}
}

static void serport_write(void *arg, long period)
{
	struct serport *p = arg;
	unsigned char mcr = 0;

	if ((*p->out[1] ^ p->invert[1]) & 1)
		mcr |= MCR_DTR;
	if ((*p->out[2] ^ p->invert[2]) & 1)
		mcr |= MCR_RTS;
	rtapi_outb(mcr, p->ioaddr + UART_MCR);
	rtapi_outb((*p->out[0] ^ p->invert[0]) & 1 ? LCR_BREAK : 0, p->ioaddr + UART_LCR);
}

static int export_port(struct serport *p, int n)
{
	char fn[HAL_NAME_LEN + 1];
	int i, err = 0;

	for (i = 0; !err && i < 4; i++) {
		err = hal_pin_bit_newf(HAL_OUT, &p->in[i], comp_id, "serport.%d.pin-%d-in", n, in_pin[i]);
		if (!err)
			err = hal_pin_bit_newf(HAL_OUT, &p->in_not[i], comp_id,
					       "serport.%d.pin-%d-in-not", n, in_pin[i]);
	}
	for (i = 0; !err && i < 3; i++) {
		err = hal_pin_bit_newf(HAL_IN, &p->out[i], comp_id, "serport.%d.pin-%d-out", n, out_pin[i]);
		if (!err)
			err = hal_param_bit_newf(HAL_RW, &p->invert[i], comp_id,
						 "serport.%d.pin-%d-out-invert", n, out_pin[i]);
	}
	if (!err)
		err = hal_param_u32_newf(HAL_RO, &p->ioaddr, comp_id, "serport.%d.ioaddr", n);
	rtapi_snprintf(fn, sizeof(fn), "serport.%d.read", n);
	if (!err)
		err = hal_export_funct(fn, serport_read, p, 0, 0, comp_id);
	rtapi_snprintf(fn, sizeof(fn), "serport.%d.write", n);
	if (!err)
		err = hal_export_funct(fn, serport_write, p, 0, 0, comp_id);
	return err;
}

static void release_all(void)
{
	int n;

	for (n = 0; n < num_ports; n++)
		if (ports[n].claimed)
			rtapi_release_region(ports[n].ioaddr, 7);
}

int rtapi_app_main(void)
{
	int n, num, err = 0;

	for (num = 0; num < MAX_PORTS && io[num] > 0; num++)
		if (io[num] > 0xfff8) {
			rtapi_print_msg(RTAPI_MSG_ERR, "serport: io=0x%x is not an I/O port address "
					"(at most 0xfff8)\n", io[num]);
			return -EINVAL;
		}
	if (num == 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "serport: give the ports' addresses: io=0x3f8[,...]\n");
		return -EINVAL;
	}
	comp_id = hal_init("serport");
	if (comp_id < 0)
		return comp_id;
	ports = hal_malloc(num * (long)sizeof(*ports));
	if (!ports) {
		rtapi_print_msg(RTAPI_MSG_ERR, "serport: out of HAL memory\n");
		hal_exit(comp_id);
		return -ENOMEM;
	}
	num_ports = num;
	for (n = 0; n < num; n++)
		ports[n].claimed = 0;
	for (n = 0; !err && n < num; n++) {
		ports[n].claimed = rtapi_request_region(io[n], 7, "serport") != 0;
		if (!ports[n].claimed) {
			rtapi_print_msg(RTAPI_MSG_ERR, "serport: port %d at 0x%x is busy or not "
					"accessible (a Linux serial driver may hold it: see "
					"setserial, \"uart none\")\n", n, io[n]);
			err = -EBUSY;
		}
		if (!err)
			err = export_port(&ports[n], n);
		if (!err)
			ports[n].ioaddr = io[n];
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
