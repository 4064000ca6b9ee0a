/* SPDX-License-Identifier: GPL-2.0-or-later */
/* homing_core.c - homing's state record, its setup and the getters motmod calls
 * (homing.h). No FP and no HAL here: the HAL pins are homing_pins.c, the state
 * machine homing_fp.c. */
#include "rtapi.h"
#include "rtapi_string.h"
#include "homing_priv.h"

struct homing_global homing_g;

int homing_setup(int num_joints, int num_extrajoints, rtapi_u32 unlock_joints_mask,
		 struct homing_joint *joints, homing_report_fn report)
{
	int j;

	if (num_joints < 1 || num_joints > HOMING_MAX_JOINTS) {
		rtapi_print_msg(RTAPI_MSG_ERR, "homing: num_joints=%d, must be 1..%d\n",
				num_joints, HOMING_MAX_JOINTS);
		return -EINVAL;
	}
	if (num_extrajoints < 0 || num_extrajoints > num_joints) {
		rtapi_print_msg(RTAPI_MSG_ERR, "homing: num_extrajoints=%d, must be 0..%d\n",
				num_extrajoints, num_joints);
		return -EINVAL;
	}
	if (!joints) {
		rtapi_print_msg(RTAPI_MSG_ERR, "homing: no joint array\n");
		return -EINVAL;
	}
	/* all-zero bytes are 0.0 for the doubles: no FP needed */
	memset(&homing_g, 0, sizeof(homing_g));
	homing_g.num_joints = num_joints;
	homing_g.num_extrajoints = num_extrajoints;
	homing_g.unlock_mask = unlock_joints_mask;
	homing_g.joints = joints;
	homing_g.report = report;
	for (j = 0; j < num_joints; j++)
		homing_g.h[j].sequence = homing_g.h[j].sequence_raw = HOME_SEQUENCE_NONE;
	return 0;
}

void homing_report(const char *fmt, ...)
{
	char msg[128];
	va_list ap;

	va_start(ap, fmt);
	rtapi_vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	if (homing_g.report)
		homing_g.report(msg);
	else
		rtapi_print_msg(RTAPI_MSG_ERR, "%s\n", msg);
}

static bool valid(int j)
{
	return j >= 0 && j < homing_g.num_joints;
}

bool get_allhomed(void)
{
	int j;

	for (j = 0; j < homing_g.num_joints; j++)
		if (homing_g.joints[j].active && !homing_g.h[j].homed)
			return false;
	return true;
}

bool get_homed(int j)
{
	return valid(j) && homing_g.h[j].homed;
}

bool get_home_is_idle(int j)
{
	return !valid(j) || homing_g.h[j].state == HOME_IDLE;
}

bool get_home_is_synchronized(int j)
{
	return valid(j) && homing_g.h[j].sequence < 0;
}

bool get_home_needs_unlock_first(int j)
{
	return valid(j) && (homing_g.h[j].flags & HOME_UNLOCK_FIRST);
}

bool get_homing(int j)
{
	return valid(j) && homing_g.h[j].homing;
}

bool get_homing_at_index_search_wait(int j)
{
	return valid(j) && homing_g.h[j].state == HOME_INDEX_SEARCH_WAIT;
}

bool get_homing_is_active(void)
{
	int j;

	if (homing_g.seq_state != HOME_SEQ_IDLE)
		return true;
	for (j = 0; j < homing_g.num_joints; j++)
		if (homing_g.h[j].homing || homing_g.h[j].state != HOME_IDLE)
			return true;
	return false;
}

bool get_index_enable(int j)
{
	return valid(j) && homing_g.h[j].index_enable;
}

int get_home_sequence(int j)
{
	return valid(j) ? homing_g.h[j].sequence : HOME_SEQUENCE_NONE;
}

bool get_home_is_volatile(int j)
{
	return valid(j) && homing_g.h[j].volatile_home;
}

int get_home_state(int j)
{
	return valid(j) ? homing_g.h[j].state : HOME_IDLE;
}
