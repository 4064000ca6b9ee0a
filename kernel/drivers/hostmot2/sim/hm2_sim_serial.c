/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_sim_serial.c - the simulated FPGA's serial modules (hostmot2.md 7.9, 7.10):
 * Buffered SPI with the Mesa 7i65 card behind BSPI 0 (when the layout has one), and
 * UARTs with a loop-back plug. Registers are addressed like the real modules: register
 * r of instance i at base + r x 0x100 + i x 0x40. Time comes from the model's ClockLow
 * tick count: an SPI frame takes bits x 2 (N + 1) ticks, a UART byte ten bit times.
 * Integer-only. */
#include "rtapi.h"
#include "rtapi_string.h"
#include "hm2_sim_model.h"

#define INST_STRIDE 0x40u
#define REG_STRIDE 0x100u

/* register and instance of addr in a 4-register module at base, or -1 */
static int decode(rtapi_u32 addr, rtapi_u32 base, int ninst, int *inst, int *word)
{
	rtapi_u32 off;

	if (!base || addr < base || addr >= base + 4 * REG_STRIDE)
		return -1;
	off = addr - base;
	*inst = (off & 0xFF) / INST_STRIDE;
	*word = (off & (INST_STRIDE - 1)) / 4;
	return *inst < ninst ? (int)(off / REG_STRIDE) : -1;
}

/* ---- the 7i65 card ---- */

static rtapi_u64 ms_ticks(struct hm2_sim_model *m, int ms)
{
	return (rtapi_u64)m->layout->clock_low / 1000 * ms;
}

/* one SPI frame to the 7i65: chip select cs, the word shifted out; returns what the
 * addressed chip shifts back */
static rtapi_u32 card_transfer(struct hm2_sim_model *m, int cs, rtapi_u32 mosi)
{
	struct sim_7i65 *c = &m->card;
	rtapi_u32 miso = 0;
	int ch, code, i;

	switch (cs) {
	case 0:			/* loop-back */
		return mosi;
	case 1:
	case 2:			/* AD5754: bits 21..19 register (0 = DAC), 18..16 channel */
		ch = (mosi >> 16) & 7;
		if (((mosi >> 19) & 7) == 0 && ch < 4 && !c->bitten)
			c->dac[(cs - 1) * 4 + ch] = (rtapi_s16)(mosi & 0xFFFF);
		return 0;
	case 3:			/* AD7329: result of the channel chosen by the previous frame */
		ch = c->adc_next;
		code = c->dac[ch] / 8;	/* +-10 V: 16-bit DAC code -> 13-bit ADC code */
		miso = ((rtapi_u32)ch << 13) | ((rtapi_u32)code & 0x1FFF);
		c->adc_next = (mosi >> 10) & 7;
		return miso;
	case 4:			/* CPLD: 0xA00 | enables; answers inputs and watchdog state */
		for (i = 0; i < SIM_7I65_INPUTS; i++)
			miso |= (rtapi_u32)(c->din[i] & 1) << i;
		miso |= (rtapi_u32)c->bitten << 8;
		if ((mosi & 0xF00) == 0xA00) {
			c->enables = mosi & 0xFF;
			c->last_cpld_tick = m->ticks;
			c->bitten = 0;
		}
		return miso;
	default:
		return 0;	/* nothing answers: MISO idles low */
	}
}

static void card_watchdog(struct hm2_sim_model *m)
{
	struct sim_7i65 *c = &m->card;
	int i;

	if (!m->layout->bspi_7i65 || c->bitten || !c->last_cpld_tick)
		return;
	if (m->ticks - c->last_cpld_tick > ms_ticks(m, 50)) {
		c->bitten = 1;		/* amplifiers disabled, outputs to 0 V */
		c->enables = 0;
		for (i = 0; i < SIM_7I65_CHANNELS; i++)
			c->dac[i] = 0;
	}
}

/* ---- BSPI ---- */

static rtapi_u64 frame_ticks(rtapi_u32 cd)
{
	rtapi_u32 bits = (cd & 0x3F) + 1, div = (cd >> 8) & 0xFF, delay = (cd >> 24) & 0x1F;

	return (rtapi_u64)bits * 2 * (div + 1) + (delay > 15 ? 0 : delay + 1);
}

static void bspi_start_head(struct sim_bspi *b, rtapi_u64 now)
{
	if (b->tx_n)
		b->busy_until = now + frame_ticks(b->cd[b->tx_cd[0] & 15]);
}

/* the head frame goes out: its reply (unless no-echo) into the receive FIFO */
static void bspi_shift_head(struct hm2_sim_model *m, int i)
{
	struct sim_bspi *b = &m->bspi[i];
	rtapi_u32 cd = b->cd[b->tx_cd[0] & 15], data = b->tx[0];
	int bits = (cd & 0x3F) + 1, k;
	rtapi_u32 mask = bits >= 32 ? 0xFFFFFFFFu : (1u << bits) - 1, miso = 0;

	if (i == 0 && m->layout->bspi_7i65)
		miso = card_transfer(m, (cd >> 16) & 0xF, data & mask) & mask;
	if (!(cd & 0x80000000u) && b->rx_n < SIM_FIFO)
		b->rx[b->rx_n++] = miso;
	for (k = 1; k < b->tx_n; k++) {
		b->tx[k - 1] = b->tx[k];
		b->tx_cd[k - 1] = b->tx_cd[k];
	}
	b->tx_n--;
}

static void bspi_advance(struct hm2_sim_model *m, int i)
{
	struct sim_bspi *b = &m->bspi[i];

	while (b->tx_n && m->ticks >= b->busy_until) {
		bspi_shift_head(m, i);
		bspi_start_head(b, b->busy_until);
	}
}

static int bspi_read(struct hm2_sim_model *m, rtapi_u32 addr, rtapi_u32 *v)
{
	int i, w, r = decode(addr, m->base_bspi, m->num_bspi, &i, &w), k;
	struct sim_bspi *b;

	if (r < 0 || r > 2)
		return 0;
	b = &m->bspi[i];
	if (r == 0) {			/* pop the receive FIFO */
		*v = b->rx_n ? b->rx[0] : 0;
		if (b->rx_n) {
			for (k = 1; k < b->rx_n; k++)
				b->rx[k - 1] = b->rx[k];
			b->rx_n--;
		}
	} else if (r == 1) {
		*v = b->cd[w & 15];
	} else {
		*v = (rtapi_u32)b->rx_n | (rtapi_u32)b->tx_n << 8;
	}
	return 1;
}

static int bspi_write(struct hm2_sim_model *m, rtapi_u32 addr, rtapi_u32 v)
{
	int i, w, r = decode(addr, m->base_bspi, m->num_bspi, &i, &w);
	struct sim_bspi *b;

	if (r < 0 || r > 2)
		return 0;
	b = &m->bspi[i];
	if (r == 0) {			/* push data with its channel descriptor number */
		if (b->tx_n == SIM_FIFO) {
			/* a burst longer than the FIFO: on the card the first frames go out
			 * while the host is still writing the rest */
			bspi_shift_head(m, i);
			bspi_start_head(b, m->ticks);
		}
		if (b->tx_n < SIM_FIFO) {
			b->tx[b->tx_n] = v;
			b->tx_cd[b->tx_n] = w;
			if (++b->tx_n == 1)
				bspi_start_head(b, m->ticks);
		}
	} else if (r == 1) {
		b->cd[15 - (b->cd_writes++ & 15)] = v;
	} else {
		b->tx_n = b->rx_n = 0;
		b->cd_writes = 0;
	}
	return 1;
}

/* ---- UART ---- */

static rtapi_u64 byte_ticks(rtapi_u32 rate)
{
	/* bit rate = rate x clock / 2^20: ten bits per byte */
	return rate ? rtapi_div_u64(10ull << 20, rate) : 0;
}

static void uart_advance(struct hm2_sim_model *m, int i)
{
	struct sim_uart *u = &m->uart[i];
	int k;

	while (u->tx_n && u->tx_rate && m->ticks >= u->busy_until) {
		if (u->rx_rate != u->tx_rate)
			u->rx_mode |= 1;	/* framing garbage: false start bit */
		else if (u->rx_n < SIM_FIFO)
			u->rx[u->rx_n++] = u->tx[0];
		else
			u->rx_mode |= 2;	/* overrun */
		for (k = 1; k < u->tx_n; k++)
			u->tx[k - 1] = u->tx[k];
		u->tx_n--;
		u->busy_until += byte_ticks(u->tx_rate);
	}
}

static int uart_read(struct hm2_sim_model *m, rtapi_u32 addr, rtapi_u32 *v)
{
	int i, w, r, k, n;
	struct sim_uart *u;

	if ((r = decode(addr, m->base_uart_tx, m->num_uart, &i, &w)) >= 0) {
		u = &m->uart[i];
		*v = r == 1 ? (rtapi_u32)u->tx_n : r == 2 ? u->tx_rate : r == 3 ? u->tx_mode : 0;
		return 1;
	}
	if ((r = decode(addr, m->base_uart_rx, m->num_uart, &i, &w)) < 0)
		return 0;
	u = &m->uart[i];
	if (r == 0) {			/* +0..+C pops 1..4 bytes, first byte lowest */
		*v = 0;
		for (n = 0; n <= (w & 3) && u->rx_n; n++) {
			*v |= (rtapi_u32)u->rx[0] << (8 * n);
			for (k = 1; k < u->rx_n; k++)
				u->rx[k - 1] = u->rx[k];
			u->rx_n--;
		}
	} else if (r == 1) {
		*v = u->rx_n;
	} else if (r == 2) {
		*v = u->rx_rate;
	} else {
		*v = (u->rx_mode & 0x7F) | (u->rx_n ? 0x80u : 0);
	}
	return 1;
}

static int uart_write(struct hm2_sim_model *m, rtapi_u32 addr, rtapi_u32 v)
{
	int i, w, r, n;
	struct sim_uart *u;

	if ((r = decode(addr, m->base_uart_tx, m->num_uart, &i, &w)) >= 0) {
		u = &m->uart[i];
		if (r == 0) {		/* +0..+C pushes 1..4 bytes */
			for (n = 0; n <= (w & 3) && u->tx_n < SIM_FIFO; n++) {
				if (!u->tx_n)
					u->busy_until = m->ticks + byte_ticks(u->tx_rate);
				u->tx[u->tx_n++] = (v >> (8 * n)) & 0xFF;
			}
		} else if (r == 1) {
			u->tx_n = 0;
		} else if (r == 2) {
			u->tx_rate = v & 0xFFFFF;
		} else {
			u->tx_mode = v;
		}
		return 1;
	}
	if ((r = decode(addr, m->base_uart_rx, m->num_uart, &i, &w)) < 0)
		return 0;
	u = &m->uart[i];
	if (r == 1)
		u->rx_n = 0;
	else if (r == 2)
		u->rx_rate = v & 0xFFFFF;
	else if (r == 3)
		u->rx_mode = v & ~3u;	/* writing clears the error flags */
	return 1;
}

void hm2_sim_serial_advance(struct hm2_sim_model *m)
{
	int i;

	for (i = 0; i < m->num_bspi && i < 2; i++)
		bspi_advance(m, i);
	card_watchdog(m);
	for (i = 0; i < m->num_uart && i < 2; i++)
		uart_advance(m, i);
}

int hm2_sim_serial_read(struct hm2_sim_model *m, rtapi_u32 addr, rtapi_u32 *v)
{
	return bspi_read(m, addr, v) || uart_read(m, addr, v);
}

int hm2_sim_serial_write(struct hm2_sim_model *m, rtapi_u32 addr, rtapi_u32 v)
{
	return bspi_write(m, addr, v) || uart_write(m, addr, v);
}
