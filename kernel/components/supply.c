/* SPDX-License-Identifier: GPL-2.0-or-later */
/* supply.c - set output pins from parameters, supply(9) (obsolete: setp and sets
 * do this now): loadrt supply [num_chan=N] (1..8, default 1). Channel N: params
 * supply.N.d (bit) and supply.N.value (float; the page's "bit" is a misprint:
 * it feeds the float outputs), pins supply.N.q, _q (bit out), supply.N.variable,
 * _variable (float out), function supply.N.update (FP). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "comp_setup.h"
#include "supply_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("set output pins from parameters (obsolete)");

static int num_chan = 1;
RTAPI_MP_INT(num_chan, "number of supply channels, 1..8");

static int comp_id;

static int export_supply(struct supply *s, int n)
{
	char fn[HAL_NAME_LEN + 1];
	int err;

	err = hal_pin_bit_newf(HAL_OUT, &s->q, comp_id, "supply.%d.q", n);
	if (!err)
		err = hal_pin_bit_newf(HAL_OUT, &s->q_not, comp_id, "supply.%d._q", n);
	if (!err)
		err = hal_pin_float_newf(HAL_OUT, &s->variable, comp_id, "supply.%d.variable", n);
	if (!err)
		err = hal_pin_float_newf(HAL_OUT, &s->variable_neg, comp_id, "supply.%d._variable", n);
	if (!err)
		err = hal_param_bit_newf(HAL_RW, &s->d, comp_id, "supply.%d.d", n);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &s->value, comp_id, "supply.%d.value", n);
	if (err)
		return err;
	rtapi_snprintf(fn, sizeof(fn), "supply.%d.update", n);
	return hal_export_funct(fn, supply_update, s, 1, 0, comp_id);
}

int rtapi_app_main(void)
{
	struct supply *all;
	int n, err;

	if (num_chan < 1 || num_chan > SUPPLY_MAX_CHAN) {
		rtapi_print_msg(RTAPI_MSG_ERR, "supply: num_chan=%d is out of range, must be 1..%d\n",
				num_chan, SUPPLY_MAX_CHAN);
		return -EINVAL;
	}
	all = comp_setup("supply", num_chan * (long)sizeof(*all), &comp_id, &err);
	if (!all)
		return err;
	for (n = 0; !err && n < num_chan; n++)
		err = export_supply(&all[n], n);
	return comp_finish(comp_id, err);
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
