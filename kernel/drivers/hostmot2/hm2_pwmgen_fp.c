/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_pwmgen_fp.c - PWM value registers (FP): duty d = value / scale in -1..1 (0 when
 * disabled), right-justified at bit 16 with bit 31 the direction; offset-mode maps
 * -1..1 to 0..100 %. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "hal.h"
#include "hm2.h"

void hm2_pwmgen_init_fp(struct hostmot2 *hm2)
{
	int i;

	for (i = 0; i < hm2->pwmgen.num; i++)
		hm2->pwmgen.inst[i].scale = 1.0;
}

void hm2_pwmgen_prepare_write_fp(struct hostmot2 *hm2)
{
	struct hm2_pwmgen *g = &hm2->pwmgen;
	int i;

	for (i = 0; i < g->num; i++) {
		struct hm2_pwmgen_inst *x = &g->inst[i];
		int pdm = x->output_type == 3;
		int bits = pdm ? 12 : g->bits;
		double t = (*x->dither && !pdm && g->md->version >= 1) ? 1.0625 : 1.0;
		double d = x->scale != 0.0 ? *x->value / x->scale : 0.0, reg;
		rtapi_u32 v;

		if (d > 1.0)
			d = 1.0;
		if (d < -1.0)
			d = -1.0;
		if (!*x->enable)
			d = 0.0;
		if (*x->offset_mode) {
			int b = bits - 1;
			double full = (double)(1 << b);

			reg = (d * (full - t) + full) * 65536.0;
		} else {
			reg = rtapi_fabs(d) * ((double)(1 << bits) - t) * 65536.0;
		}
		v = (rtapi_u32)reg & 0x7FFFFFFFu;
		if (d < 0.0)
			v |= 0x80000000u;
		g->value_wr[i] = v;
	}
}
