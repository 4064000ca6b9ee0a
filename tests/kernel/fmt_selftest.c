/* SPDX-License-Identifier: GPL-2.0-or-later */
/* fmt_selftest.c - kernel-test module (not a component): prints doubles with
 * rtapi_snprintf and rtapi_print_msg from a uses_fp task, the way FP component code
 * would. x86-64 passes a variadic call's doubles in SSE registers, so this shows
 * that the variadic entries (rtapi_print_entry_kmod.c) see them. The message
 *   fmt_selftest: 1.500 -2.25 1e+100 | 1.500 -2.25 1e+100
 * lands in /proc/rtapi/messages (tests/kernel/cases/04-fp-print.sh). The task is in
 * fmt_selftest_fp.c: this file, the init code, is compiled without SSE. */
#include "rtapi.h"
#include "rtapi_app.h"

MODULE_LICENSE("GPL");

static int module_id, task_id;
void fmt_task(void *arg);	/* fmt_selftest_fp.c */

int rtapi_app_main(void)
{
	module_id = rtapi_init("fmt_selftest");
	if (module_id < 0)
		return module_id;
	rtapi_clock_set_period(1000000);
	task_id = rtapi_task_new(fmt_task, NULL, rtapi_prio_lowest(), 0, 1);
	if (task_id < 0 || rtapi_task_start(task_id, 10000000) < 0) {
		rtapi_exit(module_id);
		return -EINVAL;
	}
	return 0;
}

void rtapi_app_exit(void)
{
	rtapi_task_delete(task_id);
	rtapi_exit(module_id);
}
