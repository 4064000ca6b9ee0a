/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rotatekins.c - rotated kinematics, kins(9), kinematics.md section 4:
 *   loadrt rotatekins
 * Nine joints; joints 0 and 1 are X and Y rotated by the C coordinate (not by a fixed
 * 45° as the page says: the table frame turns with C). No pins. Type BOTH. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "kins_module.h"
#include "kins_glue.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("rotated-table kinematics");

static int comp_id;

KINS_TYPE_IS(KINEMATICS_BOTH)
KINS_NOT_SWITCHABLE
KINS_EXPORTS

int rtapi_app_main(void)
{
	int err = kins_claim("rotatekins", kinematicsType, own_type);

	if (err)
		return err;
	comp_id = hal_init("rotatekins");
	if (comp_id < 0)
		return comp_id;
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
