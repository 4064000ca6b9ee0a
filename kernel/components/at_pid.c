/* SPDX-License-Identifier: GPL-2.0-or-later */
/* at_pid.c - PID controller with relay auto tune, at_pid(9):
 *   loadrt at_pid [num_chan=num | names=name1[,name2...]] [debug=dbg]
 * It replaces pid (same pid.N. names, RULINGS.md: never load both). Three loops
 * by default, at most 16. Per loop PREFIX: at_pid's subset of the pid pins
 * (pid_pins.h; gains are I/O pins, the tune writes them), tune-mode (bit in),
 * tune-start (bit io); parameters tune-type, tune-cycles (u32), tune-effort
 * (float); with debug=1 also ultimate-gain and ultimate-period (float out).
 * Function PREFIX.do-pid-calcs (uses FP). Tuning is at_pid_core.h. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "comp_setup.h"
#include "instance_names.h"
#include "pid_core.h"
#include "pid_pins.h"
#include "at_pid_core.h"
#include "at_pid_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("PID controller with auto tuning");

static int num_chan = -1;	/* -1: not given */
RTAPI_MP_INT(num_chan, "number of PID loops, 1..16 (default 3)");
static char *names[AT_PID_MAX];
RTAPI_MP_ARRAY_STRING(names, AT_PID_MAX, "names of the PID loops (instead of num_chan)");
static int debug;
RTAPI_MP_INT(debug, "1: export errorI, errorD, commandD, commandDD, ultimate-gain, ultimate-period");

static int comp_id;

static int at_pid_export(struct at_pid *a, const char *prefix)
{
	char fn[HAL_NAME_LEN + 1];
	int err;

	err = pid_pins_export(&a->pins, comp_id, prefix, debug != 0, true);
	if (!err)
		err = hal_pin_bit_newf(HAL_IN, &a->tune_mode, comp_id, "%s.tune-mode", prefix);
	if (!err)
		err = hal_pin_bit_newf(HAL_IO, &a->tune_start, comp_id, "%s.tune-start", prefix);
	if (!err && debug)
		err = hal_pin_float_newf(HAL_OUT, &a->ultimate_gain, comp_id, "%s.ultimate-gain",
					 prefix);
	if (!err && debug)
		err = hal_pin_float_newf(HAL_OUT, &a->ultimate_period, comp_id,
					 "%s.ultimate-period", prefix);
	if (!err)
		err = hal_param_u32_newf(HAL_RW, &a->tune_type, comp_id, "%s.tune-type", prefix);
	if (!err)
		err = hal_param_u32_newf(HAL_RW, &a->tune_cycles, comp_id, "%s.tune-cycles",
					 prefix);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &a->tune_effort, comp_id, "%s.tune-effort",
					   prefix);
	if (err)
		return err;
	a->tune_cycles = 50;	/* half cycles averaged: enough to smooth noise */
	*(volatile rtapi_u64 *)&a->tune_effort = 0x3fe0000000000000ULL;	/* 0.5 */
	rtapi_snprintf(fn, sizeof(fn), "%s.do-pid-calcs", prefix);
	return hal_export_funct(fn, at_pid_do_calcs, a, 1, 0, comp_id);
}

int rtapi_app_main(void)
{
	char prefix[HAL_NAME_LEN + 1];
	struct at_pid *all;
	int n, i, err;

	if (debug != 0 && debug != 1) {
		rtapi_print_msg(RTAPI_MSG_ERR, "at_pid: debug=%d, must be 0 or 1\n", debug);
		return -EINVAL;
	}
	if (num_chan <= 0 && (!names[0] || !names[0][0]))	/* num_chan=0: the default */
		num_chan = AT_PID_DEFAULT;
	n = instance_count("at_pid", "num_chan", num_chan, names, AT_PID_MAX, AT_PID_MAX);
	if (n < 0)
		return n;
	all = comp_setup("at_pid", n * (long)sizeof(*all), &comp_id, &err);
	if (!all)
		return err;
	for (i = 0; !err && i < n; i++) {
		instance_prefix(prefix, sizeof(prefix), "pid", names, i);
		err = at_pid_export(&all[i], prefix);
	}
	return comp_finish(comp_id, err);
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
