/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kinstest.c - drives the loaded kinematics module from HAL, as motmod calls it, so
 * a kinematics module can be tried and tested without motion:
 *   loadrt trivkins coordinates=xyyz      (or any kinematics module; first)
 *   loadrt kinstest [joints=9]
 * Pins (prefix kinstest.): joint.N.in (float IN) -> kinematicsForward -> pos.L.out
 * (float OUT, L = x y z a b c u v w), with fwd.fflags (u32 IN), fwd.iflags (u32 OUT),
 * fwd.result (s32 OUT); pos.L.in (float IN) -> kinematicsInverse, starting from
 * joint.N.in -> joint.N.out (float OUT), with inv.iflags (u32 IN), inv.fflags (u32
 * OUT), inv.result (s32 OUT). home.L (float IN): the forward's first guess, and its
 * guess after a failure (otherwise the previous result, as motion does). type (s32
 * OUT: kinematicsType), switchable (bit OUT), switch-type (s32 IN: a change calls
 * kinematicsSwitch), switch-result (s32 OUT), cycles (u32 OUT: updates run).
 * Function kinstest.update (FP). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "comp_setup.h"
#include "kinstest.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("calls the loaded kinematics module's forward and inverse each period");

static int joints = 9;
RTAPI_MP_INT(joints, "number of joints, 1..16 (default 9)");

static int comp_id;

static const char axis_names[KINS_NUM_AXES] = { 'x', 'y', 'z', 'a', 'b', 'c', 'u', 'v', 'w' };

static int export_pins(struct kinstest *k)
{
	int err = 0, n;

	for (n = 0; !err && n < k->joints; n++) {
		err = hal_pin_float_newf(HAL_IN, &k->joint_in[n], comp_id, "kinstest.joint.%d.in", n);
		if (!err)
			err = hal_pin_float_newf(HAL_OUT, &k->joint_out[n], comp_id, "kinstest.joint.%d.out", n);
	}
	for (n = 0; !err && n < KINS_NUM_AXES; n++) {
		err = hal_pin_float_newf(HAL_IN, &k->pos_in[n], comp_id, "kinstest.pos.%c.in", axis_names[n]);
		if (!err)
			err = hal_pin_float_newf(HAL_OUT, &k->pos_out[n], comp_id, "kinstest.pos.%c.out",
						 axis_names[n]);
		if (!err)
			err = hal_pin_float_newf(HAL_IN, &k->home[n], comp_id, "kinstest.home.%c", axis_names[n]);
	}
	if (!err)
		err = hal_pin_u32_newf(HAL_IN, &k->fwd_fflags, comp_id, "kinstest.fwd.fflags");
	if (!err)
		err = hal_pin_u32_newf(HAL_OUT, &k->fwd_iflags, comp_id, "kinstest.fwd.iflags");
	if (!err)
		err = hal_pin_s32_newf(HAL_OUT, &k->fwd_result, comp_id, "kinstest.fwd.result");
	if (!err)
		err = hal_pin_u32_newf(HAL_IN, &k->inv_iflags, comp_id, "kinstest.inv.iflags");
	if (!err)
		err = hal_pin_u32_newf(HAL_OUT, &k->inv_fflags, comp_id, "kinstest.inv.fflags");
	if (!err)
		err = hal_pin_s32_newf(HAL_OUT, &k->inv_result, comp_id, "kinstest.inv.result");
	if (!err)
		err = hal_pin_s32_newf(HAL_IN, &k->switch_type, comp_id, "kinstest.switch-type");
	if (!err)
		err = hal_pin_s32_newf(HAL_OUT, &k->switch_result, comp_id, "kinstest.switch-result");
	if (!err)
		err = hal_pin_s32_newf(HAL_OUT, &k->type, comp_id, "kinstest.type");
	if (!err)
		err = hal_pin_bit_newf(HAL_OUT, &k->switchable, comp_id, "kinstest.switchable");
	if (!err)
		err = hal_pin_u32_newf(HAL_OUT, &k->cycles, comp_id, "kinstest.cycles");
	if (err)
		return err;
	*k->type = kinstest_kins.type();
	*k->switchable = kinstest_kins.switchable() != 0;
	return hal_export_funct("kinstest.update", kinstest_update, k, 1, 0, comp_id);
}

struct kins_ops kinstest_kins;

int rtapi_app_main(void)
{
	struct kinstest *k;
	int err;

	if (joints < 1 || joints > KINS_MAX_JOINTS) {
		rtapi_print_msg(RTAPI_MSG_ERR, "kinstest: joints=%d, must be 1..%d\n", joints,
				KINS_MAX_JOINTS);
		return -EINVAL;
	}
	if (kins_bind(&kinstest_kins)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "kinstest: no kinematics module is loaded: load one first (e.g. 'loadrt trivkins')\n");
		return -ENOENT;
	}
	k = comp_setup("kinstest", sizeof(*k), &comp_id, &err);
	if (!k) {
		kins_unbind(&kinstest_kins);
		return err;
	}
	k->joints = joints;
	err = comp_finish(comp_id, export_pins(k));
	if (err)
		kins_unbind(&kinstest_kins);
	return err;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
	kins_unbind(&kinstest_kins);	/* after hal_exit: the update no longer runs */
}
