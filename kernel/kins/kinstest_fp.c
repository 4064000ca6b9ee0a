/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kinstest_fp.c - kinstest's realtime function: one forward and one inverse of the
 * loaded kinematics module per period, with the arguments motion would pass. */
#include "rtapi.h"
#include "kins_math.h"
#include "kinstest.h"

static void pins_to_pose(hal_float_t *const *pins, EmcPose *pose)
{
	int i;

	for (i = 0; i < KINS_NUM_AXES; i++)
		kins_pose_set(pose, i, *pins[i]);
}

void kinstest_update(void *arg, long period_ns)
{
	struct kinstest *k = arg;
	double j[KINS_MAX_JOINTS] = { 0 };
	KINEMATICS_FORWARD_FLAGS fflags;
	KINEMATICS_INVERSE_FLAGS iflags;
	EmcPose target;
	int n, rc;

	if (*k->switch_type != k->applied_switch) {
		k->applied_switch = *k->switch_type;
		*k->switch_result = kinstest_kins.switch_to(k->applied_switch);
		k->have_world = false;
	}

	/* forward from the joint inputs; the guess is the previous result, or home */
	for (n = 0; n < k->joints; n++)
		j[n] = *k->joint_in[n];
	if (!k->have_world)
		pins_to_pose(k->home, &k->world);
	fflags = *k->fwd_fflags;
	iflags = 0;
	rc = kinstest_kins.forward(j, &k->world, &fflags, &iflags);
	*k->fwd_result = rc;
	*k->fwd_iflags = (rtapi_u32)iflags;
	k->have_world = rc == 0;
	if (rc == 0)
		for (n = 0; n < KINS_NUM_AXES; n++)
			*k->pos_out[n] = kins_pose_get(&k->world, n);

	/* inverse of the pose inputs, starting from the joint inputs (the current joints) */
	pins_to_pose(k->pos_in, &target);
	iflags = *k->inv_iflags;
	fflags = 0;
	rc = kinstest_kins.inverse(&target, j, &iflags, &fflags);
	*k->inv_result = rc;
	*k->inv_fflags = (rtapi_u32)fflags;
	if (rc == 0)
		for (n = 0; n < k->joints; n++)
			*k->joint_out[n] = j[n];
	*k->cycles += 1;
}
