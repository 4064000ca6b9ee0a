/* SPDX-License-Identifier: GPL-2.0-or-later */
/* scarakins.c - SCARA kinematics, kins(9), kinematics.md section 9:
 *   loadrt scarakins [coordinates=XYZABC]
 * Pins scarakins.D1 ... scarakins.D6 (float, IN; defaults 490 340 50 250 50 50).
 * Joints: shoulder, elbow (degrees), quill (down positive), wrist (degrees), A, B.
 * Type BOTH; switchable (type 1: the identity of coordinates=). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "kins_module.h"
#include "scarakins.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("SCARA kinematics");

static char *coordinates;
RTAPI_MP_STRING(coordinates, "axis letters of the joints for switchkins type 1 (default XYZABC)");

struct scarakins_state *scarakins;
static int comp_id;

KINS_TYPE_IS(KINEMATICS_BOTH)
KINS_SWITCHABLE(&scarakins->sw)
KINS_EXPORTS

int rtapi_app_main(void)
{
	struct kins_switch sw;
	int err, i;

	err = kins_claim("scarakins", kinematicsType, own_type);
	if (!err)
		err = kins_switch_init("scarakins", coordinates, "XYZABC", &sw);
	if (err)
		return err;
	comp_id = hal_init("scarakins");
	if (comp_id < 0)
		return comp_id;
	scarakins = hal_malloc(sizeof(*scarakins));
	err = scarakins ? 0 : -ENOMEM;
	for (i = 0; !err && i < 6; i++)
		err = hal_pin_float_newf(HAL_IN, &scarakins->d[i], comp_id, "scarakins.D%d", i + 1);
	if (err) {
		hal_exit(comp_id);
		return err;
	}
	scarakins->sw = sw;
	rtapi_fpu_begin();
	scarakins_defaults(scarakins);
	rtapi_fpu_end();
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
