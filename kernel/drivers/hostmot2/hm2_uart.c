/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_uart.c - UART (GTags 9 TX and 10 RX, hostmot2.md 7.10) and its sub-driver API
 * (hm2_serial.h). No HAL objects: each instance is a name, hm2_<board>.<N>.uart.<i>,
 * printed at load. Registers of instance i, for TX and RX alike (stride from the MD):
 *   reg 0: data; the word at +0/+4/+8/+C pushes (TX) or pops (RX) 1/2/3/4 bytes,
 *          first byte in the low bits
 *   reg 1: FIFO count (bits 4..0); any write empties the FIFO
 *   reg 2: bit rate = reg x clock / 2^20
 *   reg 3: mode (TX: drive-enable delay and mode; RX: status, bit 7 = data waiting)
 * Integer-only. */
#include "rtapi.h"
#include "rtapi_string.h"
#include "hal.h"
#include "hm2.h"

#define REG_DATA 0
#define REG_COUNT 1
#define REG_RATE 2
#define REG_MODE 3
#define MAX_NAMED 16

static struct hm2_uart_inst *named[MAX_NAMED];

static struct hm2_uart_inst *find(const char *name, const char *caller)
{
	int i;

	for (i = 0; i < MAX_NAMED; i++)
		if (named[i] && name && strcmp(named[i]->name, name) == 0)
			return named[i];
	rtapi_print_msg(RTAPI_MSG_ERR, "hostmot2: %s: no UART instance named '%s' (the names are "
			"printed when the board loads)\n", caller, name ? name : "(null)");
	return 0;
}

/* Called for the TX and the RX descriptor; the instance count is settled at export. */
int hm2_uart_parse(struct hostmot2 *hm2, const struct hm2_md *md)
{
	struct hm2_uart *u = &hm2->uart;
	char err[HM2_ERRLEN];

	if (hm2_md_is_consistent(md, err, sizeof(err))) {
		HM2_ERR(hm2, "%s", err);
		return -EINVAL;
	}
	if (md->gtag == HM2_GTAG_UART_TX)
		u->tx_md = md;
	else
		u->rx_md = md;
	return 0;
}

static int settle(struct hostmot2 *hm2)
{
	struct hm2_uart *u = &hm2->uart;
	char err[HM2_ERRLEN];
	int have, n;

	if (!u->tx_md && !u->rx_md)
		return 0;
	if (!u->tx_md || !u->rx_md || u->tx_md->instances != u->rx_md->instances) {
		HM2_ERR(hm2, "inconsistent firmware: UART TX has %d instances, RX %d",
			u->tx_md ? u->tx_md->instances : 0, u->rx_md ? u->rx_md->instances : 0);
		return -EINVAL;
	}
	have = u->tx_md->instances;
	n = hm2_config_instances(&hm2->cfg, HM2_NUM_UARTS, have, err, sizeof(err));
	if (n < 0) {
		HM2_ERR(hm2, "%s", err);
		return n;
	}
	u->num = n;
	return 0;
}

/* after every MD was parsed (both halves known): count, pins */
int hm2_uart_allocate(struct hostmot2 *hm2)
{
	struct hm2_uart *u = &hm2->uart;
	int rc = settle(hm2);

	if (rc || !u->num)
		return rc;
	u->inst = hal_malloc(u->num * sizeof(*u->inst));
	if (!u->inst)
		return -ENOMEM;
	memset(u->inst, 0, u->num * sizeof(*u->inst));
	hm2_pins_allocate(hm2, HM2_GTAG_UART_TX, u->num);
	hm2_pins_allocate(hm2, HM2_GTAG_UART_RX, u->num);
	return 0;
}

int hm2_uart_export(struct hostmot2 *hm2)
{
	struct hm2_uart *u = &hm2->uart;
	int i, j;

	for (i = 0; i < u->num; i++) {
		struct hm2_uart_inst *x = &u->inst[i];

		x->hm2 = hm2;
		x->tx_mode = x->rx_mode = -1;
		rtapi_snprintf(x->name, sizeof(x->name), "%s.uart.%d", hm2->llio->name, i);
		for (j = 0; j < MAX_NAMED && named[j]; j++)
			;
		if (j == MAX_NAMED) {
			HM2_ERR(hm2, "uart: more than %d UART instances on all boards", MAX_NAMED);
			return -ENOMEM;
		}
		named[j] = x;
		HM2_INFO(hm2, "UART channel %s", x->name);
	}
	return 0;
}

void hm2_uart_cleanup(struct hostmot2 *hm2)
{
	int i, j;

	for (i = 0; i < hm2->uart.num; i++)
		for (j = 0; j < MAX_NAMED; j++)
			if (named[j] == &hm2->uart.inst[i])
				named[j] = 0;
}

static void write_setup(struct hostmot2 *hm2, int i)
{
	struct hm2_uart *u = &hm2->uart;
	struct hm2_uart_inst *x = &u->inst[i];
	rtapi_u32 v;

	x->dirty = 0;
	v = (rtapi_u32)rtapi_div_u64((rtapi_u64)x->bitrate << 20, u->tx_md->clock_freq);
	v = v > 0xFFFFF ? 0xFFFFF : v;
	hm2_write_now(hm2, hm2_md_addr(u->tx_md, REG_RATE, i), &v, 4);
	v = (rtapi_u32)rtapi_div_u64((rtapi_u64)x->bitrate << 20, u->rx_md->clock_freq);
	v = v > 0xFFFFF ? 0xFFFFF : v;
	hm2_write_now(hm2, hm2_md_addr(u->rx_md, REG_RATE, i), &v, 4);
	if (x->tx_mode >= 0) {
		v = (rtapi_u32)x->tx_mode;
		hm2_write_now(hm2, hm2_md_addr(u->tx_md, REG_MODE, i), &v, 4);
	}
	if (x->rx_mode >= 0) {
		v = (rtapi_u32)x->rx_mode;
		hm2_write_now(hm2, hm2_md_addr(u->rx_md, REG_MODE, i), &v, 4);
	}
}

void hm2_uart_force_write(struct hostmot2 *hm2)
{
	int i;

	for (i = 0; i < hm2->uart.num; i++)
		write_setup(hm2, i);
}

void hm2_uart_write(struct hostmot2 *hm2)
{
	int i;

	for (i = 0; i < hm2->uart.num; i++)
		if (hm2->uart.inst[i].dirty)
			write_setup(hm2, i);
}

/* ---- the sub-driver API ---- */

int hm2_uart_setup_chan(const char *name, rtapi_u32 bitrate, rtapi_s32 tx_mode, rtapi_s32 rx_mode)
{
	struct hm2_uart_inst *x = find(name, "hm2_uart_setup");
	rtapi_u32 max;

	if (!x)
		return -ENODEV;
	max = (rtapi_u32)rtapi_div_u64((rtapi_u64)x->hm2->uart.tx_md->clock_freq * 0xFFFFF, 1u << 20);
	if (!bitrate || bitrate > max) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hostmot2: %s: bit rate %u is not 1..%u\n", name, bitrate,
				max);
		return -EINVAL;
	}
	x->bitrate = bitrate;
	x->tx_mode = tx_mode;
	x->rx_mode = rx_mode;
	hm2_mb();
	x->dirty = 1;
	return 0;
}
EXPORT_SYMBOL(hm2_uart_setup_chan);

int hm2_uart_setup(const char *name, rtapi_u32 bitrate, rtapi_s32 tx_mode, rtapi_s32 rx_mode)
{
	return hm2_uart_setup_chan(name, bitrate, tx_mode, rx_mode);
}
EXPORT_SYMBOL(hm2_uart_setup);

int hm2_uart_send(const char *name, const unsigned char *data, int count)
{
	struct hm2_uart_inst *x = find(name, "hm2_uart_send");
	struct hostmot2 *hm2;
	rtapi_u32 fill, addr, w;
	int sent = 0, n, k, rc;

	if (!x)
		return -ENODEV;
	hm2 = x->hm2;
	if (hm2->io_error || hm2->closing)
		return -EIO;
	rc = hm2_read_now(hm2, hm2_md_addr(hm2->uart.tx_md, REG_COUNT, x - hm2->uart.inst), &fill, 4);
	if (rc < 0)
		return rc;
	fill &= 0x1F;
	if (count > HM2_UART_FIFO - (int)fill)
		count = fill >= HM2_UART_FIFO ? 0 : HM2_UART_FIFO - (int)fill;
	addr = hm2_md_addr(hm2->uart.tx_md, REG_DATA, x - hm2->uart.inst);
	while (sent < count) {
		n = count - sent > 4 ? 4 : count - sent;
		for (w = 0, k = 0; k < n; k++)
			w |= (rtapi_u32)data[sent + k] << (8 * k);
		rc = hm2_write_now(hm2, addr + 4 * (n - 1), &w, 4);	/* +4(n-1): n bytes */
		if (rc < 0)
			return rc;
		sent += n;
	}
	rc = hm2_tram_flush_writes(hm2);
	return rc < 0 ? rc : sent;
}
EXPORT_SYMBOL(hm2_uart_send);

int hm2_uart_read(const char *name, unsigned char *data)
{
	struct hm2_uart_inst *x = find(name, "hm2_uart_read");
	struct hostmot2 *hm2;
	rtapi_u32 fill, addr, w;
	int got = 0, n, k, rc;

	if (!x)
		return -ENODEV;
	hm2 = x->hm2;
	if (hm2->io_error || hm2->closing)
		return -EIO;
	rc = hm2_read_now(hm2, hm2_md_addr(hm2->uart.rx_md, REG_COUNT, x - hm2->uart.inst), &fill, 4);
	if (rc < 0)
		return rc;
	fill &= 0x1F;
	if (fill > HM2_UART_FIFO)
		fill = HM2_UART_FIFO;
	addr = hm2_md_addr(hm2->uart.rx_md, REG_DATA, x - hm2->uart.inst);
	while (got < (int)fill) {
		n = (int)fill - got > 4 ? 4 : (int)fill - got;
		rc = hm2_read_now(hm2, addr + 4 * (n - 1), &w, 4);
		if (rc < 0)
			return rc;
		for (k = 0; k < n; k++)
			data[got + k] = (w >> (8 * k)) & 0xFF;
		got += n;
	}
	return got;
}
EXPORT_SYMBOL(hm2_uart_read);
