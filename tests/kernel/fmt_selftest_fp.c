/* SPDX-License-Identifier: GPL-2.0-or-later */
/* fmt_selftest_fp.c - the FP task of fmt_selftest.c, alone in its file (the kernel
 * flavor's FP rule): prints doubles with rtapi_snprintf and rtapi_print_msg, the way FP
 * component code would, from a uses_fp task (inside an FPU section). */
#include "rtapi.h"

void fmt_task(void *arg);

static volatile double values[3] = { 1.5, -2.25, 1e100 };	/* not constants: real FP args */

void fmt_task(void *arg)
{
	char buf[80];

	(void)arg;
	rtapi_snprintf(buf, sizeof(buf), "%.3f %g %g", values[0], values[1], values[2]);
	rtapi_print_msg(RTAPI_MSG_ERR, "fmt_selftest: %s | %.3f %g %g\n", buf, values[0],
			values[1], values[2]);
	for (;;)
		rtapi_task_wait();
}
