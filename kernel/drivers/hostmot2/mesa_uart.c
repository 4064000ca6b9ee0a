/* SPDX-License-Identifier: GPL-2.0-or-later */
/* mesa_uart.c - a simple sub-driver of hostmot2's UART (hostmot2(9) "UART"), and the
 * example of the UART API (hm2_serial.h):
 *   loadrt mesa_uart uart_chans=hm2_5i23.0.uart.0 [bitrate=115200]
 * Instance mesa-uart.N per UART name, with
 *   tx-data-00..15 (u32 in, low byte sent), tx-bytes (s32 in), tx-send (bit I/O: set
 *   TRUE to queue tx-bytes bytes; the send function clears it), rx-data-00..15 (u32
 *   out), rx-bytes (s32 out: bytes taken by the last receive), rx-count (u32 out: all
 *   bytes received)
 * and the functions mesa-uart.N.send and mesa-uart.N.receive, to be added to the
 * thread that runs the board's read and write. Integer-only. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "hal.h"
#include "hm2_serial.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("Byte transfers on a hostmot2 UART");

#define MAX_UARTS 8

static char *uart_chans[MAX_UARTS];
RTAPI_MP_ARRAY_STRING(uart_chans, MAX_UARTS, "UART instances, e.g. hm2_5i23.0.uart.0");
static int bitrate = 115200;
RTAPI_MP_INT(bitrate, "bit rate of every UART, bit/s");

struct muart {
	char name[HAL_NAME_LEN + 1];
	hal_u32_t *tx_data[HM2_UART_FIFO], *rx_data[HM2_UART_FIFO];
	hal_s32_t *tx_bytes, *rx_bytes;
	hal_bit_t *tx_send;
	hal_u32_t *rx_count;
};

static int comp_id;

static void send(void *arg, long period)
{
	struct muart *u = arg;
	unsigned char buf[HM2_UART_FIFO];
	int n = *u->tx_bytes, i;

	if (!*u->tx_send)
		return;
	if (n > HM2_UART_FIFO)
		n = HM2_UART_FIFO;
	for (i = 0; i < n; i++)
		buf[i] = *u->tx_data[i] & 0xFF;
	if (n <= 0 || hm2_uart_send(u->name, buf, n) == n)
		*u->tx_send = 0;	/* else: the FIFO was full, try again next time */
}

static void receive(void *arg, long period)
{
	struct muart *u = arg;
	unsigned char buf[HM2_UART_FIFO];
	int n = hm2_uart_read(u->name, buf), i;

	if (n < 0)
		n = 0;
	for (i = 0; i < n; i++)
		*u->rx_data[i] = buf[i];
	*u->rx_bytes = n;
	*u->rx_count += n;
}

static int setup(struct muart *u, int k)
{
	char f[HAL_NAME_LEN + 1];
	int i, rc = 0;

	for (i = 0; i < HM2_UART_FIFO && !rc; i++) {
		rc = hal_pin_u32_newf(HAL_IN, &u->tx_data[i], comp_id, "mesa-uart.%d.tx-data-%02d", k, i);
		if (!rc)
			rc = hal_pin_u32_newf(HAL_OUT, &u->rx_data[i], comp_id, "mesa-uart.%d.rx-data-%02d", k, i);
	}
	if (!rc) rc = hal_pin_s32_newf(HAL_IN, &u->tx_bytes, comp_id, "mesa-uart.%d.tx-bytes", k);
	if (!rc) rc = hal_pin_bit_newf(HAL_IO, &u->tx_send, comp_id, "mesa-uart.%d.tx-send", k);
	if (!rc) rc = hal_pin_s32_newf(HAL_OUT, &u->rx_bytes, comp_id, "mesa-uart.%d.rx-bytes", k);
	if (!rc) rc = hal_pin_u32_newf(HAL_OUT, &u->rx_count, comp_id, "mesa-uart.%d.rx-count", k);
	if (!rc) rc = hm2_uart_setup(u->name, (rtapi_u32)bitrate, -1, -1);
	rtapi_snprintf(f, sizeof(f), "mesa-uart.%d.send", k);
	if (!rc) rc = hal_export_funct(f, send, u, 0, 0, comp_id);
	rtapi_snprintf(f, sizeof(f), "mesa-uart.%d.receive", k);
	if (!rc) rc = hal_export_funct(f, receive, u, 0, 0, comp_id);
	return rc;
}

int rtapi_app_main(void)
{
	struct muart *u;
	int n, k, rc = 0;

	comp_id = hal_init("mesa_uart");
	if (comp_id < 0)
		return comp_id;
	for (n = 0; n < MAX_UARTS && uart_chans[n] && *uart_chans[n];)
		n++;
	if (!n || bitrate <= 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "mesa_uart: %s\n", !n ? "uart_chans= is required (the "
				"UART names hostmot2 printed, e.g. hm2_5i23.0.uart.0)" : "bitrate must be > 0");
		hal_exit(comp_id);
		return -EINVAL;
	}
	u = hal_malloc(n * sizeof(*u));
	if (!u) {
		hal_exit(comp_id);
		return -ENOMEM;
	}
	for (k = 0; k < n && !rc; k++) {
		const char *name = uart_chans[k];

		while (*name == ' ')
			name++;
		rtapi_strlcpy(u[k].name, name, sizeof(u[k].name));
		rc = setup(&u[k], k);
		if (rc)
			rtapi_print_msg(RTAPI_MSG_ERR, "mesa_uart: uart_chans=%s: cannot use it (%d)\n",
					u[k].name, rc);
	}
	if (rc) {
		hal_exit(comp_id);
		return rc;
	}
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
