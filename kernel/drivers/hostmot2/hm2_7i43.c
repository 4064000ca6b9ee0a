/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_7i43.c - board driver for the Mesa 7i43, an EPP parallel-port card with a
 * Spartan-3 FPGA (200K or 400K) configured through a CPLD (hm2_7i43(9);
 * hm2-transports.md section 2):
 *   loadrt hostmot2
 *   loadrt hm2_7i43 ioaddr=0x378 config="firmware=hm2/7i43/SVST4_4.BIT num_stepgens=4"
 * ioaddr, ioaddr_hi, epp_wide and config are comma-separated arrays, one entry per
 * board (up to 4; ioaddr -1 ends the list). Each port is claimed through
 * hal_parport_get (a Linux parport number below 16, or an address), put in EPP mode
 * (ECR 0x94 when it has a high address), and the board is reset: the running
 * firmware is told to reconfigure, the CPLD pulses PROG_B, and DONE must then be
 * low. The CPLD reports the FPGA's size, which picks the part a bitfile must be for;
 * hostmot2 then programs it from firmware= (required: the reset leaves the FPGA
 * empty) through program_fpga below. Transfers are EPP cycles (hm2_7i43_epp.c); a
 * timeout sets the board's io_error, and hostmot2 leaves the board alone until the
 * user clears it. Not thread-safe: no read_gpio/write_gpio. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "hal.h"
#include "hal_parport.h"
#include "hm2_llio.h"
#include "hm2_boards.h"
#include "hm2_bitfile.h"
#include "hm2_7i43_epp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("Mesa 7i43 (EPP parallel port) for hostmot2");

#define MAX_BOARDS 4
#define ECR_EPP 0x94		/* ECR mode 100 = EPP (base_hi + 2) */
#define CONTROL_IDLE 0x04	/* /INIT high, strobes released, data port output */
#define CPLD_DATA 0x00		/* address byte: the CPLD's data register */
#define CPLD_CONTROL 0x01	/* address byte: its control register (PROG_B, DONE) */
#define RECONFIG_ADDR 0x7F7F	/* with data 0x5A: the firmware reconfigures itself */
#define RECONFIG_BYTE 0x5A
#define ADDR_COOKIE 0x0100
#define HM2_COOKIE 0x55AACAFEu

static int ioaddr[MAX_BOARDS] = { 0x378, -1, -1, -1 };
RTAPI_MP_ARRAY_INT(ioaddr, MAX_BOARDS, "parallel port of each board: an address, or a Linux "
		   "parport number below 16 (-1 ends the list)");
static int ioaddr_hi[MAX_BOARDS];
RTAPI_MP_ARRAY_INT(ioaddr_hi, MAX_BOARDS, "the ports' high (ECP) addresses: 0 = ioaddr + 0x400, "
		   "-1 = none");
static int epp_wide[MAX_BOARDS] = { 1, 1, 1, 1 };
RTAPI_MP_ARRAY_INT(epp_wide, MAX_BOARDS, "1 = 32-bit EPP accesses, 0 = byte accesses");
static char *config[MAX_BOARDS];
RTAPI_MP_ARRAY_STRING(config, MAX_BOARDS, "hostmot2 config string of each board");
static int debug_epp;
RTAPI_MP_INT(debug_epp, "log every EPP word transfer (not those of programming)");

struct board_7i43 {
	struct hm2_llio llio;
	struct epp_port epp;
	hal_parport_t port;
	int have_port, registered;
};

static int comp_id;
static struct board_7i43 *boards;
static int num_boards;

/* After a transfer: a timeout makes the board's io_error TRUE (hostmot2 then stops
 * talking to it until the user clears it). */
static int check_timeout(struct board_7i43 *b, const char *what, rtapi_u32 addr, int size)
{
	if (!epp_timed_out(&b->epp))
		return 0;
	rtapi_print_msg(RTAPI_MSG_ERR, "%s: EPP timeout on %s of %d bytes at 0x%04x: check the "
			"cable, the board's power and the port's EPP mode\n", b->llio.name, what,
			size, addr);
	if (b->llio.io_error)
		*b->llio.io_error = 1;
	b->llio.needs_reset = 1;
	return -EIO;
}

/* whole aligned words inside the space EPP reaches (hm2-transports.md 2.3) */
static int bad_span(rtapi_u32 addr, int size)
{
	return size <= 0 || (size & 3) || (addr & 3) || addr + size > EPP_MAX_ADDR;
}

static int epp_read(struct hm2_llio *llio, rtapi_u32 addr, void *buf, int size)
{
	struct board_7i43 *b = llio->priv;

	if (bad_span(addr, size))
		return -EINVAL;
	epp_read_words(&b->epp, addr, buf, size / 4);
	return check_timeout(b, "read", addr, size);
}

static int epp_write(struct hm2_llio *llio, rtapi_u32 addr, const void *buf, int size)
{
	struct board_7i43 *b = llio->priv;

	if (bad_span(addr, size))
		return -EINVAL;
	epp_write_words(&b->epp, addr, buf, size / 4);
	return check_timeout(b, "write", addr, size);
}

/* The firmware told to reconfigure (twice), then PROG_B pulsed through the CPLD;
 * the FPGA is then empty and the CPLD answers EPP cycles. */
static int epp_reset(struct hm2_llio *llio)
{
	struct board_7i43 *b = llio->priv;
	rtapi_u8 done;
	int i;

	for (i = 0; i < 2; i++) {
		epp_addr8(&b->epp, RECONFIG_ADDR & 0xFF);
		epp_addr8(&b->epp, RECONFIG_ADDR >> 8);
		epp_write8(&b->epp, RECONFIG_BYTE);
	}
	epp_addr8(&b->epp, CPLD_CONTROL);
	epp_write8(&b->epp, 0);		/* PROG_B low: configuration cleared */
	rtapi_delay(2000);		/* >= 300 ns */
	epp_write8(&b->epp, 1);		/* released */
	rtapi_sleep_ns(2000000);
	done = epp_read8(&b->epp) & 1;
	if (epp_timed_out(&b->epp)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: EPP timeout while resetting the board: is a "
				"7i43 connected to the port at 0x%x, powered, and is the port in "
				"EPP mode?\n", llio->name, b->epp.base);
		return -EIO;
	}
	if (done) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: /DONE is not low after the CPLD reset (is the "
				"board set to load its FPGA from the parallel port, W4 and W5 down?)\n",
				llio->name);
		return -EIO;
	}
	return 0;
}

/* The CPLD clocks each byte written to its data register into the FPGA's parallel
 * configuration port, which takes the bitstream's bytes bit-reversed. Then the
 * cookie proves the firmware runs; a port that fails 32-bit accesses is switched
 * to byte accesses. */
static int epp_program_fpga(struct hm2_llio *llio, const void *bitstream, rtapi_u32 size)
{
	struct board_7i43 *b = llio->priv;
	const rtapi_u8 *p = bitstream;
	rtapi_u32 i, cookie = 0;

	epp_addr8(&b->epp, CPLD_DATA);
	for (i = 0; i < size; i++)
		epp_write8(&b->epp, hm2_bitfile_reverse(p[i]));
	if (epp_timed_out(&b->epp)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: EPP timeout while programming the FPGA\n",
				llio->name);
		return -EIO;
	}
	epp_read_words(&b->epp, ADDR_COOKIE, &cookie, 1);
	if (!epp_timed_out(&b->epp) && cookie == HM2_COOKIE)
		return 0;
	if (b->epp.wide) {
		rtapi_print_msg(RTAPI_MSG_WARN, "%s: no HostMot2 cookie with 32-bit EPP accesses "
				"(0x%08x): using byte accesses (epp_wide=0)\n", llio->name, cookie);
		b->epp.wide = 0;
		epp_read_words(&b->epp, ADDR_COOKIE, &cookie, 1);
		if (!epp_timed_out(&b->epp) && cookie == HM2_COOKIE)
			return 0;
	}
	rtapi_print_msg(RTAPI_MSG_ERR, "%s: the FPGA does not run HostMot2 after programming "
			"%u bytes (cookie 0x%08x, expected 0x%08x)\n", llio->name, size, cookie,
			HM2_COOKIE);
	return -EIO;
}

/* firmware= among the config string's words: the reset at every load empties the
 * FPGA, so there is nothing to run without it */
static int has_firmware(const char *cfg)
{
	const char *s;

	for (s = cfg; s && (s = strstr(s, "firmware=")); s++)
		if (s == cfg || s[-1] == ' ' || s[-1] == '\t')
			return 1;
	return 0;
}

static int setup_board(int k)
{
	const struct hm2_board_info *info = hm2_board_find("7i43");
	struct board_7i43 *b = &boards[k];
	struct hm2_llio *llio = &b->llio;
	unsigned short hi = ioaddr_hi[k] == -1 ? (unsigned short)-1 : (unsigned short)ioaddr_hi[k];
	int i, rc;

	rtapi_snprintf(llio->name, sizeof(llio->name), "hm2_7i43.%d", k);
	if (ioaddr[k] < 0 || ioaddr[k] > 0xFFF8 || ioaddr_hi[k] < -1 || ioaddr_hi[k] > 0xFFFD) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: ioaddr=0x%x ioaddr_hi=0x%x: not an I/O port "
				"address\n", llio->name, ioaddr[k], ioaddr_hi[k]);
		return -EINVAL;
	}
	if (!has_firmware(config[k])) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: config needs firmware=hm2/7i43/<file>.BIT: the "
				"FPGA is reset and programmed at every load\n", llio->name);
		return -EINVAL;
	}
	rc = hal_parport_get(comp_id, &b->port, (unsigned short)ioaddr[k], hi, HAL_PARPORT_MODE_EPP);
	if (rc) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: cannot claim the parallel port %s0x%x\n", llio->name,
				ioaddr[k] < 16 ? "number " : "at ", ioaddr[k]);
		return rc;
	}
	b->have_port = 1;
	b->epp.base = b->port.base;
	b->epp.wide = epp_wide[k] != 0;
	b->epp.debug = 0;		/* not while programming */
	b->epp.name = llio->name;
	if (b->port.base_hi)
		rtapi_outb(ECR_EPP, b->port.base_hi + 2);
	rtapi_outb(CONTROL_IDLE, b->port.base + 2);
	epp_timed_out(&b->epp);		/* a stale flag from before */

	llio->comp_id = comp_id;
	llio->num_ioport_connectors = info->connectors;
	llio->pins_per_connector = info->pins_per_connector;
	for (i = 0; i < info->connectors && i < HM2_LLIO_MAX_CONNECTORS; i++)
		llio->ioport_connector_name[i] = info->connector[i];
	llio->num_leds = info->leds;
	llio->threadsafe = 0;
	llio->split_read = 0;
	llio->read = epp_read;
	llio->write = epp_write;
	llio->reset = epp_reset;
	llio->program_fpga = epp_program_fpga;
	llio->priv = b;
	rc = epp_reset(llio);
	if (rc)
		return rc;
	/* the CPLD's data register, bit 0: the FPGA's size */
	epp_addr8(&b->epp, CPLD_DATA);
	llio->fpga_part_number = info->part[epp_read8(&b->epp) & 1];
	rtapi_print_msg(RTAPI_MSG_INFO, "%s: 7i43 with a %s FPGA on the parallel port at 0x%x "
			"(high 0x%x)\n", llio->name, llio->fpga_part_number, b->port.base,
			b->port.base_hi);
	rc = hm2_register(llio, config[k]);
	if (rc)
		return rc;
	b->registered = 1;
	b->epp.debug = debug_epp;
	return 0;
}

static void close_boards(void)
{
	int k;

	for (k = 0; k < num_boards; k++) {
		if (boards[k].registered)
			hm2_unregister(&boards[k].llio);
		if (boards[k].have_port)
			hal_parport_release(&boards[k].port);
	}
}

int rtapi_app_main(void)
{
	void *mem;

	for (num_boards = 0; num_boards < MAX_BOARDS && ioaddr[num_boards] != -1;)
		num_boards++;
	if (!num_boards) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_7i43: ioaddr= names no port (the first entry "
				"is -1)\n");
		return -EINVAL;
	}
	comp_id = hm2_llio_init_boards("hm2_7i43", "ioaddr", config, MAX_BOARDS, num_boards,
				       sizeof(*boards), &mem);
	if (comp_id < 0)
		return comp_id;
	boards = mem;
	return hm2_llio_setup_boards(comp_id, num_boards, setup_board, close_boards);
}

void rtapi_app_exit(void)
{
	close_boards();
	hal_exit(comp_id);
}
