/* SPDX-License-Identifier: GPL-2.0-or-later */
/* genhexkins.c - hexapod (Stewart platform) kinematics, kins(9), kinematics.md
 * section 6:
 *   loadrt genhexkins [coordinates=XYZABC]
 * Pins (prefix genhexkins., as LinuxCNC 2.9): base.N.x/y/z, platform.N.x/y/z,
 * base-n.N.x/y/z, platform-n.N.x/y/z (float IN, N = 0..5: the joint positions and
 * universal-joint axes), screw-lead, spindle-offset, tool-offset, max-error,
 * convergence-criterion (float IN), limit-iterations (u32 IN), correction.N (float
 * OUT), last-iterations, max-iterations (u32 OUT), fwd-kins-fail (bit OUT), and
 * x y z a b c (float OUT: the last pose the forward found, for displays).
 * Joints 0..5 are strut lengths. Type BOTH; switchable (type 1: the identity of
 * coordinates=). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "kins_module.h"
#include "genhexkins.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("hexapod kinematics");

static char *coordinates;
RTAPI_MP_STRING(coordinates, "axis letters of the joints for switchkins type 1 (default XYZABC)");

struct genhexkins_state *genhexkins;
static int comp_id;

KINS_TYPE_IS(KINEMATICS_BOTH)
KINS_SWITCHABLE(&genhexkins->sw)
KINS_EXPORTS

/* genhexkins.GROUP.N.x/y/z */
static int export_points(hal_float_t *(*p)[3], const char *group)
{
	static const char xyz[3] = { 'x', 'y', 'z' };
	int err = 0, n, k;

	for (n = 0; !err && n < KINS_HEX_STRUTS; n++)
		for (k = 0; !err && k < 3; k++)
			err = hal_pin_float_newf(HAL_IN, &p[n][k], comp_id, "genhexkins.%s.%d.%c",
						 group, n, xyz[k]);
	return err;
}

static int export_pins(struct genhexkins_state *s)
{
	static const char *const pos[6] = { "x", "y", "z", "a", "b", "c" };
	int err, n;

	err = export_points(s->base, "base");
	if (!err)
		err = export_points(s->platform, "platform");
	if (!err)
		err = export_points(s->base_n, "base-n");
	if (!err)
		err = export_points(s->platform_n, "platform-n");
	if (!err)
		err = hal_pin_float_newf(HAL_IN, &s->screw_lead, comp_id, "genhexkins.screw-lead");
	for (n = 0; !err && n < KINS_HEX_STRUTS; n++)
		err = hal_pin_float_newf(HAL_OUT, &s->correction[n], comp_id, "genhexkins.correction.%d", n);
	if (!err)
		err = hal_pin_float_newf(HAL_IN, &s->spindle_offset, comp_id, "genhexkins.spindle-offset");
	if (!err)
		err = hal_pin_float_newf(HAL_IN, &s->tool_offset, comp_id, "genhexkins.tool-offset");
	if (!err)
		err = hal_pin_float_newf(HAL_IN, &s->max_error, comp_id, "genhexkins.max-error");
	if (!err)
		err = hal_pin_float_newf(HAL_IN, &s->criterion, comp_id, "genhexkins.convergence-criterion");
	if (!err)
		err = hal_pin_u32_newf(HAL_IN, &s->limit_iterations, comp_id, "genhexkins.limit-iterations");
	if (!err)
		err = hal_pin_u32_newf(HAL_OUT, &s->last_iterations, comp_id, "genhexkins.last-iterations");
	if (!err)
		err = hal_pin_u32_newf(HAL_OUT, &s->max_iterations, comp_id, "genhexkins.max-iterations");
	if (!err)
		err = hal_pin_bit_newf(HAL_OUT, &s->fwd_kins_fail, comp_id, "genhexkins.fwd-kins-fail");
	for (n = 0; !err && n < 6; n++)
		err = hal_pin_float_newf(HAL_OUT, &s->pos[n], comp_id, "genhexkins.%s", pos[n]);
	return err;
}

int rtapi_app_main(void)
{
	struct kins_switch sw;
	int err;

	err = kins_claim("genhexkins", kinematicsType, own_type);
	if (!err)
		err = kins_switch_init("genhexkins", coordinates, "XYZABC", &sw);
	if (err)
		return err;
	comp_id = hal_init("genhexkins");
	if (comp_id < 0)
		return comp_id;
	genhexkins = hal_malloc(sizeof(*genhexkins));
	err = genhexkins ? export_pins(genhexkins) : -ENOMEM;
	if (err) {
		hal_exit(comp_id);
		return err;
	}
	genhexkins->sw = sw;
	rtapi_fpu_begin();
	genhexkins_defaults(genhexkins);
	rtapi_fpu_end();
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
