/* SPDX-License-Identifier: GPL-2.0-or-later */
/* genserkins.c - general serial-arm kinematics, kins(9), kinematics.md section 10:
 *   loadrt genserkins [coordinates=XYZABCUVW]
 * Pins (prefix genserkins.): A-N, ALPHA-N (radians), D-N (float IN, N = 0..5: the
 * modified Denavit-Hartenberg parameters of link N; defaults a PUMA-like arm),
 * unrotate-N (s32 IN, 0), max-iterations (u32 IN, 100), last-iterations (u32 OUT).
 * Joints 0..5 in degrees, 6..8 carry U V W. Type BOTH; switchable (type 1: the
 * identity of coordinates=). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "kins_module.h"
#include "genserkins.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("general serial kinematics");

static char *coordinates;
RTAPI_MP_STRING(coordinates, "axis letters of the joints for switchkins type 1 (default XYZABCUVW)");

struct genserkins_state *genserkins;
static int comp_id;

KINS_TYPE_IS(KINEMATICS_BOTH)
KINS_SWITCHABLE(&genserkins->sw)
KINS_EXPORTS

static int export_pins(struct genserkins_state *s)
{
	int err = 0, n;

	for (n = 0; !err && n < KINS_GENSER_LINKS; n++) {
		err = hal_pin_float_newf(HAL_IN, &s->a[n], comp_id, "genserkins.A-%d", n);
		if (!err)
			err = hal_pin_float_newf(HAL_IN, &s->alpha[n], comp_id, "genserkins.ALPHA-%d", n);
		if (!err)
			err = hal_pin_float_newf(HAL_IN, &s->d[n], comp_id, "genserkins.D-%d", n);
		if (!err)
			err = hal_pin_s32_newf(HAL_IN, &s->unrotate[n], comp_id, "genserkins.unrotate-%d", n);
	}
	if (!err)
		err = hal_pin_u32_newf(HAL_IN, &s->max_iterations, comp_id, "genserkins.max-iterations");
	if (!err)
		err = hal_pin_u32_newf(HAL_OUT, &s->last_iterations, comp_id, "genserkins.last-iterations");
	if (!err)
		*s->max_iterations = 100;
	return err;
}

int rtapi_app_main(void)
{
	struct kins_switch sw;
	int err;

	err = kins_claim("genserkins", kinematicsType, own_type);
	if (!err)
		err = kins_switch_init("genserkins", coordinates, "XYZABCUVW", &sw);
	if (err)
		return err;
	comp_id = hal_init("genserkins");
	if (comp_id < 0)
		return comp_id;
	genserkins = hal_malloc(sizeof(*genserkins));
	err = genserkins ? export_pins(genserkins) : -ENOMEM;
	if (err) {
		hal_exit(comp_id);
		return err;
	}
	genserkins->sw = sw;
	rtapi_fpu_begin();
	genserkins_defaults(genserkins);
	rtapi_fpu_end();
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
