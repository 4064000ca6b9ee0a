/* SPDX-License-Identifier: GPL-2.0-or-later */
/* maxkins.c - 5-axis kinematics of the "max" mill, kins(9), kinematics.md section 7:
 *   loadrt maxkins
 * Head tilting about B, rotary table C; pins maxkins.pivot-length (float, I/O,
 * default 0.666) and maxkins.conventional-directions (bit, IN). Nine joints; type BOTH. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "kins_module.h"
#include "kins_glue.h"
#include "maxkins.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("tilting head / rotary table 5-axis kinematics");

struct maxkins_pins *maxkins;
static int comp_id;

KINS_TYPE_IS(KINEMATICS_BOTH)
KINS_NOT_SWITCHABLE
KINS_EXPORTS

int rtapi_app_main(void)
{
	int err = kins_claim("maxkins", kinematicsType, own_type);

	if (err)
		return err;
	comp_id = hal_init("maxkins");
	if (comp_id < 0)
		return comp_id;
	maxkins = hal_malloc(sizeof(*maxkins));
	err = maxkins ? 0 : -ENOMEM;
	if (!err)
		err = hal_pin_float_newf(HAL_IO, &maxkins->pivot_length, comp_id, "maxkins.pivot-length");
	if (!err)
		err = hal_pin_bit_newf(HAL_IN, &maxkins->conventional, comp_id,
				       "maxkins.conventional-directions");
	if (err) {
		hal_exit(comp_id);
		return err;
	}
	rtapi_fpu_begin();
	maxkins_defaults(maxkins);
	rtapi_fpu_end();
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
