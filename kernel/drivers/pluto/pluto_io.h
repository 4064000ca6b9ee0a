/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pluto_io.h - what pluto_servo and pluto_step share around their function
 * blocks: the digital inputs and outputs with their -not/-invert names, the
 * communication-error and debug params, and the first read of a period, which
 * notices an EPP timeout. Integer only: used from the *_fp.c read/write functions
 * and from the init code alike. */
#ifndef PLUTO_IO_H
#define PLUTO_IO_H

#include "rtapi.h"
#include "hal.h"
#include "pluto_common.h"

#define PLUTO_MAX_DIO 20

struct pluto_io {
	int ndout, ndin;
	hal_bit_t *dout[PLUTO_MAX_DIO];
	hal_bit_t dout_invert[PLUTO_MAX_DIO];			/* RW */
	hal_bit_t *din[PLUTO_MAX_DIO], *din_not[PLUTO_MAX_DIO];
	hal_u32_t communication_error;				/* RW */
	hal_s32_t debug_0, debug_1;				/* RW */
};

/* PREFIX.dout.NN, PREFIX.dout.NN-invert, PREFIX.din.NN, PREFIX.din.NN-not,
 * PREFIX.communication-error, PREFIX.debug-0, PREFIX.debug-1. */
static inline int pluto_export_io(struct pluto_io *io, int comp_id, const char *prefix,
				  int ndout, int ndin)
{
	int i, err = 0;

	io->ndout = ndout;
	io->ndin = ndin;
	for (i = 0; !err && i < ndout; i++) {
		err = hal_pin_bit_newf(HAL_IN, &io->dout[i], comp_id, "%s.dout.%02d", prefix, i);
		if (!err)
			err = hal_param_bit_newf(HAL_RW, &io->dout_invert[i], comp_id,
						 "%s.dout.%02d-invert", prefix, i);
	}
	for (i = 0; !err && i < ndin; i++) {
		err = hal_pin_bit_newf(HAL_OUT, &io->din[i], comp_id, "%s.din.%02d", prefix, i);
		if (!err)
			err = hal_pin_bit_newf(HAL_OUT, &io->din_not[i], comp_id, "%s.din.%02d-not",
					       prefix, i);
	}
	if (!err)
		err = hal_param_u32_newf(HAL_RW, &io->communication_error, comp_id,
					 "%s.communication-error", prefix);
	if (!err)
		err = hal_param_s32_newf(HAL_RW, &io->debug_0, comp_id, "%s.debug-0", prefix);
	if (!err)
		err = hal_param_s32_newf(HAL_RW, &io->debug_1, comp_id, "%s.debug-1", prefix);
	return err;
}

/* The level dout k drives: the pin, XOR its -invert param. */
static inline int pluto_dout_level(const struct pluto_io *io, int k)
{
	return (*io->dout[k] ^ io->dout_invert[k]) & 1;
}

/* Reads the four function-block words from EPP address 0. A timeout counts a
 * communication error, and after any error the board is left alone (the user
 * resets the param): returns -1 without touching word[]. */
static inline int pluto_read_words(const hal_parport_t *port, int wide, struct pluto_io *io,
				   rtapi_u32 word[4])
{
	unsigned int base = port->base;
	int i;

	pluto_addr(base, 0);
	word[0] = pluto_read32(base, wide);
	if (pluto_timed_out(base)) {
		io->communication_error++;
		pluto_clear_timeout(base);
	}
	if (io->communication_error)
		return -1;
	for (i = 1; i < 4; i++)
		word[i] = pluto_read32(base, wide);
	return 0;
}

/* The input word that follows the function blocks, onto din and din-not. */
static inline void pluto_read_din(const hal_parport_t *port, int wide, struct pluto_io *io)
{
	rtapi_u32 in = pluto_read32(port->base, wide);
	int i;

	for (i = 0; i < io->ndin; i++) {
		*io->din[i] = (in >> i) & 1;
		*io->din_not[i] = !*io->din[i];
	}
}

#endif /* PLUTO_IO_H */
