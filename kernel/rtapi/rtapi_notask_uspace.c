/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_notask_uspace.c - the task API in user processes (ULAPI build): tasks belong to
 * realtime code only (intro(3rtapi)), so every call says so and fails with -ENOSYS. */
#include "rtapi.h"

static int no_tasks(const char *what)
{
	rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: %s: tasks exist only in realtime code (RTAPI), "
			"not in user programs\n", what);
	return -ENOSYS;
}

int rtapi_task_new(void (*taskcode)(void *), void *arg, int prio,
		   unsigned long stacksize, int uses_fp)
{
	return no_tasks("rtapi_task_new");
}

int rtapi_task_delete(int task_id)
{
	return no_tasks("rtapi_task_delete");
}

int rtapi_task_start(int task_id, unsigned long int period_nsec)
{
	return no_tasks("rtapi_task_start");
}

int rtapi_task_pause(int task_id)
{
	return no_tasks("rtapi_task_pause");
}

int rtapi_task_resume(int task_id)
{
	return no_tasks("rtapi_task_resume");
}

void rtapi_task_wait(void)
{
	no_tasks("rtapi_task_wait");
}

void rtapi_wait(void)
{
	no_tasks("rtapi_wait");
}

int rtapi_task_self(void)
{
	return -EINVAL;		/* a user program is never a task */
}

long long rtapi_task_overruns(int task_id)
{
	return no_tasks("rtapi_task_overruns");
}
