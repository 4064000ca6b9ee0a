/* SPDX-License-Identifier: GPL-2.0-or-later */
/* trivkins.c - identity kinematics, kins(9), kinematics.md section 2:
 *   loadrt trivkins [coordinates=XYZABCUVW] [kinstype=1|b|f|i]
 * Joint N drives the axis of the N-th letter; a letter may repeat (a gantry: both
 * joints get the axis; the first listed joint gives the axis its position). No pins. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "kins_module.h"
#include "kins_glue.h"
#include "trivkins.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("identity kinematics");

static char *coordinates;
RTAPI_MP_STRING(coordinates, "axis letters of joints 0, 1, ... (default XYZABCUVW)");
static char *kinstype;
RTAPI_MP_STRING(kinstype, "1 identity (default), b both, f forward only, i inverse only");

struct trivkins_state trivkins;
static int comp_id;

KINS_TYPE_IS(trivkins.type)
KINS_NOT_SWITCHABLE
KINS_EXPORTS

int rtapi_app_main(void)
{
	const struct kins_coords *c = &trivkins.coords;
	int err;

	err = kins_claim("trivkins", kinematicsType, own_type);
	if (!err)
		err = kins_coords_parse("trivkins", coordinates ? coordinates : "XYZABCUVW",
					KINS_MAX_JOINTS, &trivkins.coords);
	if (!err)
		err = kins_kinstype_parse("trivkins", kinstype ? kinstype : "1", &trivkins.type);
	if (err)
		return err;
	if (!kins_coords_is_trivial(c)) {
		kins_coords_print("trivkins", c);
		/* a lathe (XZ) is fine as identity; any other mapping jogs joints apart */
		if (trivkins.type == KINEMATICS_IDENTITY &&
		    !(c->num_joints == 2 && c->axis[0] == 0 && c->axis[1] == 2))
			rtapi_print_msg(RTAPI_MSG_INFO,
					"trivkins: coordinates=%s is not XYZABCUVW: kinstype=both is recommended\n",
					coordinates);
	}
	comp_id = hal_init("trivkins");
	if (comp_id < 0)
		return comp_id;
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
