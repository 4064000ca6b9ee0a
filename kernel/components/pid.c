/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pid.c - proportional/integral/derivative controller, pid(9) and the PID section
 * of the realtime components chapter:
 *   loadrt pid [num_chan=num | names=name1[,name2...]] [debug=dbg]
 * Three loops by default (RULINGS.md), at most 16. Per loop PREFIX (pid.N or the
 * name): the pins of pid_pins.h and the function PREFIX.do-pid-calcs (uses FP),
 * one per loop so loops may run in different threads. The math is pid_core.h. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "comp_setup.h"
#include "instance_names.h"
#include "pid_core.h"
#include "pid_pins.h"
#include "pid_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("PID controller");

static int num_chan = -1;	/* -1: not given */
RTAPI_MP_INT(num_chan, "number of PID loops, 1..16 (default 3)");
static char *names[PID_MAX];
RTAPI_MP_ARRAY_STRING(names, PID_MAX, "names of the PID loops (instead of num_chan)");
static int debug;
RTAPI_MP_INT(debug, "1: export the errorI, errorD, commandD, commandDD, commandDDD pins");

static int comp_id;

static int pid_export(struct pid_loop *p, const char *prefix)
{
	char fn[HAL_NAME_LEN + 1];
	int err;

	err = pid_pins_export(&p->pins, comp_id, prefix, debug != 0, false);
	if (err)
		return err;
	rtapi_snprintf(fn, sizeof(fn), "%s.do-pid-calcs", prefix);
	return hal_export_funct(fn, pid_do_calcs, p, 1, 0, comp_id);
}

int rtapi_app_main(void)
{
	char prefix[HAL_NAME_LEN + 1];
	struct pid_loop *all;
	int n, i, err;

	if (debug != 0 && debug != 1) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pid: debug=%d, must be 0 or 1\n", debug);
		return -EINVAL;
	}
	if (num_chan <= 0 && (!names[0] || !names[0][0]))	/* num_chan=0: the default */
		num_chan = PID_DEFAULT;
	n = instance_count("pid", "num_chan", num_chan, names, PID_MAX, PID_MAX);
	if (n < 0)
		return n;
	all = comp_setup("pid", n * (long)sizeof(*all), &comp_id, &err);
	if (!all)
		return err;
	for (i = 0; !err && i < n; i++) {
		instance_prefix(prefix, sizeof(prefix), "pid", names, i);
		err = pid_export(&all[i], prefix);
	}
	return comp_finish(comp_id, err);
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
