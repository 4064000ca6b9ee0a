/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sim_16550.c - a simulated 16550 UART (small-boards.md §4.1) behind io..io+7
 * (rtapi_iosim.h): loadrt sim_16550 io=0x3f8[,...]. Per UART N:
 *   sim-16550.N.dcd / dsr / cts / ri (bit IN) the modem-status lines, TRUE = asserted;
 *   sim-16550.N.dtr / rts / out1 / out2 / break (bit OUT) the modem-control lines;
 *   sim-16550.N.mcr / lcr (u32 OUT) the registers as written; msr-reads, mcr-writes,
 *   lcr-writes (u32 OUT) count accesses.
 * In loopback (MCR bit 4) the status lines follow the control lines as on a real
 * 16550 (CTS = RTS, DSR = DTR, RI = OUT1, DCD = OUT2) and a transmitted byte is
 * received. The divisor latch is kept; no serial timing is simulated. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_iosim.h"
#include "hal.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("simulated 16550 UART");

#define SIM_MAX 4
static int io[SIM_MAX];
RTAPI_MP_ARRAY_INT(io, SIM_MAX, "I/O addresses of the simulated UARTs");

#define MCR_LOOP 0x10
#define LCR_DLAB 0x80

struct sim_uart {		/* HAL memory; touched only by port accesses */
	hal_bit_t *dcd, *dsr, *cts, *ri;
	hal_bit_t *dtr, *rts, *out1, *out2, *brk;
	hal_u32_t *mcr, *lcr, *msr_reads, *mcr_writes, *lcr_writes;
	unsigned char mcr_reg, lcr_reg, ier, scr, dll, dlm, rx;
	int rx_full, handle;
	char name[24];
};

static int comp_id;
static struct sim_uart *uarts;
static int num_uarts;

static unsigned char msr_byte(struct sim_uart *u)
{
	int dcd = *u->dcd, dsr = *u->dsr, cts = *u->cts, ri = *u->ri;

	if (u->mcr_reg & MCR_LOOP) {
		cts = u->mcr_reg & 0x02;
		dsr = u->mcr_reg & 0x01;
		ri = u->mcr_reg & 0x04;
		dcd = u->mcr_reg & 0x08;
	}
	return (cts ? 0x10 : 0) | (dsr ? 0x20 : 0) | (ri ? 0x40 : 0) | (dcd ? 0x80 : 0);
}

static unsigned char uart_inb(void *dev, unsigned int off)
{
	struct sim_uart *u = dev;
	int dlab = u->lcr_reg & LCR_DLAB;

	switch (off) {
	case 0:
		if (dlab)
			return u->dll;
		u->rx_full = 0;
		return u->rx;
	case 1: return dlab ? u->dlm : u->ier;
	case 2: return 0x01;		/* IIR: no interrupt pending */
	case 3: return u->lcr_reg;
	case 4: return u->mcr_reg;
	case 5: return 0x60 | (u->rx_full ? 0x01 : 0);	/* transmitter empty */
	case 6:
		++*u->msr_reads;
		return msr_byte(u);
	default: return u->scr;
	}
}

static void uart_outb(void *dev, unsigned int off, unsigned char b)
{
	struct sim_uart *u = dev;
	int dlab = u->lcr_reg & LCR_DLAB;

	switch (off) {
	case 0:
		if (dlab) {
			u->dll = b;
		} else if (u->mcr_reg & MCR_LOOP) {
			u->rx = b;
			u->rx_full = 1;
		}
		break;
	case 1:
		if (dlab)
			u->dlm = b;
		else
			u->ier = b & 0x0f;
		break;
	case 3:
		++*u->lcr_writes;
		u->lcr_reg = b;
		*u->lcr = b;
		*u->brk = (b & 0x40) != 0;
		break;
	case 4:
		++*u->mcr_writes;
		u->mcr_reg = b & 0x1f;
		*u->mcr = u->mcr_reg;
		/* in loopback the outputs are held inactive, the lines loop inside */
		*u->dtr = !(b & MCR_LOOP) && (b & 0x01);
		*u->rts = !(b & MCR_LOOP) && (b & 0x02);
		*u->out1 = !(b & MCR_LOOP) && (b & 0x04);
		*u->out2 = !(b & MCR_LOOP) && (b & 0x08);
		break;
	case 7:
		u->scr = b;
		break;
	default:
		break;		/* FCR: no FIFO is simulated */
	}
}

static const struct rtapi_iosim_ops uart_ops = { uart_inb, uart_outb };

static int bit_pin(hal_pin_dir_t dir, hal_bit_t **p, int n, const char *what)
{
	return hal_pin_bit_newf(dir, p, comp_id, "sim-16550.%d.%s", n, what);
}

static int u32_pin(hal_u32_t **p, int n, const char *what)
{
	return hal_pin_u32_newf(HAL_OUT, p, comp_id, "sim-16550.%d.%s", n, what);
}

static int export_uart(struct sim_uart *u, int n)
{
	int err = bit_pin(HAL_IN, &u->dcd, n, "dcd");

	if (!err) err = bit_pin(HAL_IN, &u->dsr, n, "dsr");
	if (!err) err = bit_pin(HAL_IN, &u->cts, n, "cts");
	if (!err) err = bit_pin(HAL_IN, &u->ri, n, "ri");
	if (!err) err = bit_pin(HAL_OUT, &u->dtr, n, "dtr");
	if (!err) err = bit_pin(HAL_OUT, &u->rts, n, "rts");
	if (!err) err = bit_pin(HAL_OUT, &u->out1, n, "out1");
	if (!err) err = bit_pin(HAL_OUT, &u->out2, n, "out2");
	if (!err) err = bit_pin(HAL_OUT, &u->brk, n, "break");
	if (!err) err = u32_pin(&u->mcr, n, "mcr");
	if (!err) err = u32_pin(&u->lcr, n, "lcr");
	if (!err) err = u32_pin(&u->msr_reads, n, "msr-reads");
	if (!err) err = u32_pin(&u->mcr_writes, n, "mcr-writes");
	if (!err) err = u32_pin(&u->lcr_writes, n, "lcr-writes");
	return err;
}

static void unregister_all(void)
{
	int n;

	for (n = 0; n < num_uarts; n++)
		if (uarts[n].handle >= 0)
			rtapi_iosim_unregister(uarts[n].handle);
}

int rtapi_app_main(void)
{
	int n, num, err = 0;

	for (num = 0; num < SIM_MAX && io[num] > 0; num++)
		if (io[num] > 0xfff8) {
			rtapi_print_msg(RTAPI_MSG_ERR, "sim_16550: io=0x%x: at most 0xfff8\n", io[num]);
			return -EINVAL;
		}
	if (num == 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "sim_16550: give the UARTs' addresses: io=0x...\n");
		return -EINVAL;
	}
	comp_id = hal_init("sim_16550");
	if (comp_id < 0)
		return comp_id;
	uarts = hal_malloc(num * (long)sizeof(*uarts));
	if (!uarts) {
		rtapi_print_msg(RTAPI_MSG_ERR, "sim_16550: out of HAL memory\n");
		hal_exit(comp_id);
		return -ENOMEM;
	}
	for (n = 0; n < num; n++)
		uarts[n].handle = -1;
	num_uarts = num;
	for (n = 0; !err && n < num; n++) {
		struct sim_uart *u = &uarts[n];

		rtapi_snprintf(u->name, sizeof(u->name), "sim-16550.%d", n);
		u->mcr_reg = u->lcr_reg = u->ier = u->scr = u->dll = u->dlm = u->rx = 0;
		u->rx_full = 0;
		err = export_uart(u, n);
		if (!err) {
			u->handle = rtapi_iosim_register(io[n], 8, &uart_ops, u, u->name);
			err = u->handle < 0 ? u->handle : 0;
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
