/* SPDX-License-Identifier: GPL-2.0-or-later */
/* mesa_7i65.h - state of one 7i65 (mesa_7i65.c: loading, HAL objects; mesa_7i65_fp.c:
 * the per-cycle frames, run by hostmot2's read and write through BSPI callbacks). */
#ifndef MESA_7I65_H
#define MESA_7I65_H

#include "rtapi.h"
#include "hal.h"

#define M7I65_CHANNELS 8
#define M7I65_INPUTS 4

/* BSPI descriptors (chip selects of the card) */
#define M7I65_CHAN_DAC0 1	/* CS1: AD5754, analogue 0..3 */
#define M7I65_CHAN_DAC1 2	/* CS2: AD5754, analogue 4..7 */
#define M7I65_CHAN_ADC 3	/* CS3: AD7329 */
#define M7I65_CHAN_CPLD 4	/* CS4: enables, inputs, watchdog */

struct m7i65 {
	char bspi[HAL_NAME_LEN + 1];
	hal_float_t *out[M7I65_CHANNELS], *in[M7I65_CHANNELS];
	hal_bit_t *enable[M7I65_CHANNELS], *din[M7I65_INPUTS], *has_bit;
	hal_float_t scale[M7I65_CHANNELS];
	hal_bit_t bipolar[M7I65_CHANNELS];
	rtapi_u32 *dac_wr[M7I65_CHANNELS];	/* frames (hostmot2's words) */
	rtapi_u32 *dac_rd[M7I65_CHANNELS];	/* unused: the DACs do not reply */
	rtapi_u32 *adc_wr[M7I65_CHANNELS], *adc_rd[M7I65_CHANNELS];
	rtapi_u32 *cpld_wr, *cpld_rd;
	int released;
};

int m7i65_write_fp(void *arg);	/* BSPI write function */
int m7i65_read_fp(void *arg);	/* BSPI read function */
void m7i65_init_fp(struct m7i65 *c);

#endif /* MESA_7I65_H */
