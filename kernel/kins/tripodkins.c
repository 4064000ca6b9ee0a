/* SPDX-License-Identifier: GPL-2.0-or-later */
/* tripodkins.c - tripod kinematics, kins(9), kinematics.md section 5:
 *   loadrt tripodkins
 * Joints 0, 1, 2 are the distances of the controlled point from the motors at
 * (0,0,0), (Bx,0,0) and (Cx,Cy,0): pins tripodkins.Bx, tripodkins.Cx, tripodkins.Cy
 * (float, I/O, default 1.0). Type BOTH. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "kins_module.h"
#include "kins_glue.h"
#include "tripodkins.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("tripod kinematics");

struct tripodkins_pins *tripodkins;
static int comp_id;

KINS_TYPE_IS(KINEMATICS_BOTH)
KINS_NOT_SWITCHABLE
KINS_EXPORTS

int rtapi_app_main(void)
{
	int err = kins_claim("tripodkins", kinematicsType, own_type);

	if (err)
		return err;
	comp_id = hal_init("tripodkins");
	if (comp_id < 0)
		return comp_id;
	tripodkins = hal_malloc(sizeof(*tripodkins));
	err = tripodkins ? 0 : -ENOMEM;
	if (!err)
		err = hal_pin_float_newf(HAL_IO, &tripodkins->bx, comp_id, "tripodkins.Bx");
	if (!err)
		err = hal_pin_float_newf(HAL_IO, &tripodkins->cx, comp_id, "tripodkins.Cx");
	if (!err)
		err = hal_pin_float_newf(HAL_IO, &tripodkins->cy, comp_id, "tripodkins.Cy");
	if (err) {
		hal_exit(comp_id);
		return err;
	}
	rtapi_fpu_begin();
	tripodkins_defaults(tripodkins);
	rtapi_fpu_end();
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
