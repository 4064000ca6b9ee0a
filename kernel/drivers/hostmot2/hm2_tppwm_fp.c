/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_tppwm_fp.c - 3pwmgen arithmetic (FP): each phase value / scale, clipped to
 * +-1, as a 10-bit duty around 512 (= 50 %); the setup word with the sample time. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "hal.h"
#include "hm2.h"

void hm2_tppwm_init_fp(struct hostmot2 *hm2)
{
	int i;

	for (i = 0; i < hm2->tppwm.num; i++) {
		hm2->tppwm.inst[i].scale = 1.0;
		hm2->tppwm.inst[i].sample_time = 0.5;
	}
}

static rtapi_u32 duty(double v, double scale)
{
	double d = scale != 0.0 ? v / scale : 0.0;

	if (d > 1.0)
		d = 1.0;
	if (d < -1.0)
		d = -1.0;
	return (rtapi_u32)(rtapi_s32)(d * 511.0 + 512.5) & 0x3FF;
}

void hm2_tppwm_prepare_write_fp(struct hostmot2 *hm2)
{
	struct hm2_tppwm *t = &hm2->tppwm;
	int i;

	for (i = 0; i < t->num; i++) {
		struct hm2_tppwm_inst *x = &t->inst[i];
		double st = x->sample_time;

		t->value_wr[i] = duty(*x->a_value, x->scale) | duty(*x->b_value, x->scale) << 10 |
				 duty(*x->c_value, x->scale) << 20;
		if (st < 0.0)
			st = 0.0;
		if (st > 1.0)
			st = 1.0;
		x->setup = hm2_tppwm_deadtime_reg(hm2, i) | (x->fault_invert ? 1u << 15 : 0) |
			   (rtapi_u32)(st * 1023.0) << 16;
	}
}
