/* SPDX-License-Identifier: GPL-2.0-or-later */
/* mesa_7i65_fp.c - the 7i65's frames, each cycle (FP; run inside hostmot2's read and
 * write, which are FP functions):
 *   DAC (AD5754, 24 bits): register 0, channel in bits 18..16, the signed 16-bit code
 *     of out x scale volts (+-10 V = +-32767) in 15..0;
 *   ADC (AD7329, 16 bits): write bit 15, the next channel in 12..10; the reply has
 *     the channel of the result in 15..13 and a 13-bit signed code, 409.6 per volt;
 *   CPLD (12 bits): 0xA00 | the 8 enables; the reply has the digital inputs in bits
 *     3..0 and the card's watchdog in bit 8. */
#include "rtapi.h"
#include "hal.h"
#include "mesa_7i65.h"

void m7i65_init_fp(struct m7i65 *c)
{
	int i;

	for (i = 0; i < M7I65_CHANNELS; i++)
		c->scale[i] = 10.0;
}

int m7i65_write_fp(void *arg)
{
	struct m7i65 *c = arg;
	rtapi_u32 en = 0;
	int i;

	for (i = 0; i < M7I65_CHANNELS; i++) {
		double v = *c->out[i], lo = c->bipolar[i] ? -1.0 : 0.0, code;

		if (v > 1.0)
			v = 1.0;
		if (v < lo)
			v = lo;
		code = v * c->scale[i] * 3276.7;
		if (code > 32767.0)
			code = 32767.0;
		if (code < -32767.0)
			code = -32767.0;
		*c->dac_wr[i] = (rtapi_u32)(i & 3) << 16 | ((rtapi_u32)(rtapi_s32)code & 0xFFFF);
		*c->adc_wr[i] = 0x8000u | (rtapi_u32)i << 10;
		if (*c->enable[i])
			en |= 1u << i;
	}
	*c->cpld_wr = 0xA00u | en;
	return 0;
}

int m7i65_read_fp(void *arg)
{
	struct m7i65 *c = arg;
	int i;

	for (i = 0; i < M7I65_CHANNELS; i++) {
		rtapi_u32 r = *c->adc_rd[i];
		rtapi_s32 code = (rtapi_s32)((r & 0x1FFF) << 19) >> 19;	/* 13-bit signed */

		*c->in[(r >> 13) & 7] = code / 409.6;
	}
	for (i = 0; i < M7I65_INPUTS; i++)
		*c->din[i] = (*c->cpld_rd >> i) & 1;
	*c->has_bit = (*c->cpld_rd >> 8) & 1;
	return 0;
}
