/* SPDX-License-Identifier: GPL-2.0-or-later */
/* homing_pins.c - homing's HAL pins (homing.h lists them): created by homing_init()
 * with their EMC2 axis.N.* aliases, copied to and from homing's state once per period
 * by read_homing_in_pins() / write_homing_out_pins(). No FP. */
#include "rtapi.h"
#include "hal.h"
#include "homing_priv.h"

struct homing_pins {		/* one per joint, in hal_malloc() memory */
	hal_bit_t *home_sw_in;	/* joint.N.home-sw-in */
	hal_bit_t *index_enable;	/* joint.N.index-enable (IO) */
	hal_bit_t *homing;	/* joint.N.homing */
	hal_bit_t *homed;	/* joint.N.homed */
	hal_s32_t *home_state;	/* joint.N.home-state */
	hal_bit_t *unlock;	/* joint.N.unlock, NULL unless in unlock_joints_mask */
	hal_bit_t *is_unlocked;	/* joint.N.is-unlocked, same */
};

static struct homing_pins *pins;	/* NULL until homing_init() succeeded */

/* joint.N.<what> plus its alias axis.N.<what> (motion.md 5). */
static int alias(int j, const char *what)
{
	char name[HAL_NAME_LEN + 1], emc2[HAL_NAME_LEN + 1];
	int err;

	rtapi_snprintf(name, sizeof(name), "joint.%d.%s", j, what);
	rtapi_snprintf(emc2, sizeof(emc2), "axis.%d.%s", j, what);
	err = hal_pin_alias(name, emc2);
	if (err)
		rtapi_print_msg(RTAPI_MSG_ERR, "homing: cannot alias %s as %s\n", name, emc2);
	return err;
}

static int export_joint(struct homing_pins *p, int comp_id, int j, bool unlock)
{
	int err;

	err = hal_pin_bit_newf(HAL_IN, &p->home_sw_in, comp_id, "joint.%d.home-sw-in", j);
	if (!err)
		err = hal_pin_bit_newf(HAL_IO, &p->index_enable, comp_id, "joint.%d.index-enable", j);
	if (!err)
		err = hal_pin_bit_newf(HAL_OUT, &p->homing, comp_id, "joint.%d.homing", j);
	if (!err)
		err = hal_pin_bit_newf(HAL_OUT, &p->homed, comp_id, "joint.%d.homed", j);
	if (!err)
		err = hal_pin_s32_newf(HAL_OUT, &p->home_state, comp_id, "joint.%d.home-state", j);
	if (!err && unlock)
		err = hal_pin_bit_newf(HAL_OUT, &p->unlock, comp_id, "joint.%d.unlock", j);
	if (!err && unlock)
		err = hal_pin_bit_newf(HAL_IN, &p->is_unlocked, comp_id, "joint.%d.is-unlocked", j);
	if (err) {
		rtapi_print_msg(RTAPI_MSG_ERR, "homing: cannot create the homing pins of joint %d\n", j);
		return err;
	}
	err = alias(j, "home-sw-in");
	if (!err)
		err = alias(j, "index-enable");
	if (!err)
		err = alias(j, "homing");
	if (!err)
		err = alias(j, "homed");
	if (!err)
		err = alias(j, "home-state");
	if (!err && unlock)
		err = alias(j, "unlock");
	if (!err && unlock)
		err = alias(j, "is-unlocked");
	return err;
}

int homing_init(int comp_id, int num_joints, int num_extrajoints, rtapi_u32 unlock_joints_mask,
		struct homing_joint *joints, homing_report_fn report)
{
	struct homing_pins *all;
	int j, err;

	pins = NULL;
	err = homing_setup(num_joints, num_extrajoints, unlock_joints_mask, joints, report);
	if (err)
		return err;
	all = hal_malloc(num_joints * (long)sizeof(*all));
	if (!all) {
		rtapi_print_msg(RTAPI_MSG_ERR, "homing: out of HAL memory\n");
		return -ENOMEM;
	}
	for (j = 0; j < num_joints; j++) {
		err = export_joint(&all[j], comp_id, j, (unlock_joints_mask >> j) & 1);
		if (err)
			return err;
	}
	pins = all;
	return 0;
}

void read_homing_in_pins(void)
{
	int j;

	if (!pins)
		return;
	for (j = 0; j < homing_g.num_joints; j++) {
		struct homing_priv *h = &homing_g.h[j];

		h->home_sw = *pins[j].home_sw_in;
		h->index_enable = *pins[j].index_enable;
		if (pins[j].is_unlocked)
			h->is_unlocked = *pins[j].is_unlocked;
	}
}

void write_homing_out_pins(void)
{
	int j;

	if (!pins)
		return;
	for (j = 0; j < homing_g.num_joints; j++) {
		struct homing_priv *h = &homing_g.h[j];

		*pins[j].index_enable = h->index_enable;
		*pins[j].homing = h->homing;
		*pins[j].homed = h->homed;
		*pins[j].home_state = h->state;
		if (pins[j].unlock)
			*pins[j].unlock = h->unlock;
	}
}
