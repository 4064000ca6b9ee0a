/* SPDX-License-Identifier: GPL-2.0-or-later */
/* gantrykins.c - EMC2's gantry kinematics, gantrykins(9), kinematics.md section 3:
 *   loadrt gantrykins [coordinates=XYZABC]
 * Parameters gantrykins.joint-N (s32, RW, N = 0..8): the axis (0..8 = X..W) of joint
 * N, -1 for none, initialized from coordinates=. Inverse: each joint gets its axis;
 * forward: each axis gets its highest-numbered joint. Type BOTH. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "kins_module.h"
#include "kins_glue.h"
#include "gantrykins.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("gantry kinematics: several joints on one axis");

static char *coordinates;
RTAPI_MP_STRING(coordinates, "axis letters of joints 0, 1, ... (default XYZABC, at most 9)");

struct gantrykins_params *gantrykins;
static int comp_id;

KINS_TYPE_IS(KINEMATICS_BOTH)
KINS_NOT_SWITCHABLE
KINS_EXPORTS

int rtapi_app_main(void)
{
	struct kins_coords c;
	int err, n;

	err = kins_claim("gantrykins", kinematicsType, own_type);
	if (!err)
		err = kins_coords_parse("gantrykins", coordinates ? coordinates : "XYZABC",
					GANTRYKINS_JOINTS, &c);
	if (err)
		return err;
	comp_id = hal_init("gantrykins");
	if (comp_id < 0)
		return comp_id;
	gantrykins = hal_malloc(sizeof(*gantrykins));
	err = gantrykins ? 0 : -ENOMEM;
	for (n = 0; !err && n < GANTRYKINS_JOINTS; n++) {
		err = hal_param_s32_newf(HAL_RW, &gantrykins->joint[n], comp_id, "gantrykins.joint-%d", n);
		gantrykins->joint[n] = n < c.num_joints ? c.axis[n] : -1;
	}
	if (err) {
		hal_exit(comp_id);
		return err;
	}
	kins_coords_print("gantrykins", &c);
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
