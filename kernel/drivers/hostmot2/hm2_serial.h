/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_serial.h - what hostmot2 offers sub-drivers of its serial modules (hostmot2(9),
 * "BSPI" and "UART"): a sub-driver such as mesa_7i65 names a channel the way the
 * board printed it at load ("hm2_5i23.0.bspi.0", "hm2_5i23.0.uart.0") and gets
 * transfers on it. Every function returns a negative errno (-ENODEV: no such
 * channel) with a message naming the channel and the reason.
 *
 * BSPI: describe each chip select once (hm2_bspi_setup_chan), register the frames to
 * send every cycle (hm2_tram_add_bspi_frame, then hm2_allocate_bspi_tram), and hand
 * over a write function (fills the frames' words; runs in the board's write(), before
 * they are sent) and a read function (runs in the board's read(), after the replies
 * of the previous cycle's frames were read into the frames' read words). Both run in
 * the board's thread, with floating point allowed. hm2_bspi_release() undoes all of
 * it (a sub-driver calls it when it unloads; it waits for a callback in progress).
 * Descriptors and hm2_bspi_write_chan() words are sent by the next write().
 *
 * UART: hm2_uart_setup() sets the bit rates (applied by the next write()); send and
 * read move bytes at once and must be called from a function in the same thread as
 * the board's read and write. */
#ifndef HM2_SERIAL_H
#define HM2_SERIAL_H

#include "rtapi.h"

#define HM2_BSPI_FRAMES 32	/* frames per BSPI instance and cycle */
#define HM2_UART_FIFO 16	/* bytes in each UART FIFO */

/* chan: descriptor 0..15; cs: chip select 0..15; bits 1..64 -> 1..32 per word;
 * khz: bit clock (rounded down to ClockLow / 2(N + 1)); delay_ns: chip-select to clock
 * delay (0 = none); noclear: keep the frame open after this word; noecho: no reply
 * word in the receive FIFO. */
int hm2_bspi_setup_chan(const char *name, int chan, int cs, int bits, rtapi_u32 khz, int delay_ns,
			int cpol, int cpha, int noclear, int noecho);
int hm2_bspi_write_chan(const char *name, int chan, rtapi_u32 val);
int hm2_tram_add_bspi_frame(const char *name, int chan, rtapi_u32 **wbuf, rtapi_u32 **rbuf);
int hm2_allocate_bspi_tram(const char *name);
int hm2_bspi_set_read_function(const char *name, int (*func)(void *subdata), void *subdata);
int hm2_bspi_set_write_function(const char *name, int (*func)(void *subdata), void *subdata);
int hm2_bspi_release(const char *name);

/* bitrate in bit/s; tx_mode/rx_mode: mode registers, -1 = leave as they are */
int hm2_uart_setup(const char *name, rtapi_u32 bitrate, rtapi_s32 tx_mode, rtapi_s32 rx_mode);
int hm2_uart_setup_chan(const char *name, rtapi_u32 bitrate, rtapi_s32 tx_mode, rtapi_s32 rx_mode);
/* queue up to count bytes; returns how many fit in the transmit FIFO */
int hm2_uart_send(const char *name, const unsigned char *data, int count);
/* take what arrived, up to HM2_UART_FIFO bytes; returns the count */
int hm2_uart_read(const char *name, unsigned char *data);

#endif /* HM2_SERIAL_H */
