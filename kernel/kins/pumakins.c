/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pumakins.c - PUMA arm kinematics, kins(9), kinematics.md section 8:
 *   loadrt pumakins [coordinates=XYZABC]
 * Pins pumakins.A2, A3, D3, D4, D6 (float, IN; defaults 300 50 70 400 70). Six
 * joints in degrees. Type BOTH; switchable (type 1: the identity of coordinates=). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "kins_module.h"
#include "pumakins.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("PUMA arm kinematics");

static char *coordinates;
RTAPI_MP_STRING(coordinates, "axis letters of the joints for switchkins type 1 (default XYZABC)");

struct pumakins_state *pumakins;
static int comp_id;

KINS_TYPE_IS(KINEMATICS_BOTH)
KINS_SWITCHABLE(&pumakins->sw)
KINS_EXPORTS

int rtapi_app_main(void)
{
	struct kins_switch sw;
	int err;

	err = kins_claim("pumakins", kinematicsType, own_type);
	if (!err)
		err = kins_switch_init("pumakins", coordinates, "XYZABC", &sw);
	if (err)
		return err;
	comp_id = hal_init("pumakins");
	if (comp_id < 0)
		return comp_id;
	pumakins = hal_malloc(sizeof(*pumakins));
	err = pumakins ? 0 : -ENOMEM;
	if (!err)
		err = hal_pin_float_newf(HAL_IN, &pumakins->a2, comp_id, "pumakins.A2");
	if (!err)
		err = hal_pin_float_newf(HAL_IN, &pumakins->a3, comp_id, "pumakins.A3");
	if (!err)
		err = hal_pin_float_newf(HAL_IN, &pumakins->d3, comp_id, "pumakins.D3");
	if (!err)
		err = hal_pin_float_newf(HAL_IN, &pumakins->d4, comp_id, "pumakins.D4");
	if (!err)
		err = hal_pin_float_newf(HAL_IN, &pumakins->d6, comp_id, "pumakins.D6");
	if (err) {
		hal_exit(comp_id);
		return err;
	}
	pumakins->sw = sw;
	rtapi_fpu_begin();
	pumakins_defaults(pumakins);
	rtapi_fpu_end();
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
