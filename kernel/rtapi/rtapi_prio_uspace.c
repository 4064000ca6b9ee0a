/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_prio_uspace.c - task priorities (rtapi_prio(3rtapi)) for the simulated-realtime
 * flavor. The numbers are SCHED_FIFO priorities, higher = more urgent, from the lowest
 * FIFO priority up to one below the highest: the top level stays free for the kernel's
 * own per-CPU threads (watchdog, migration). */
#include <sched.h>
#include "rtapi.h"

int rtapi_prio_highest(void)
{
	return sched_get_priority_max(SCHED_FIFO) - 1;
}

int rtapi_prio_lowest(void)
{
	return sched_get_priority_min(SCHED_FIFO);
}

int rtapi_prio_next_higher(int prio)
{
	int high = rtapi_prio_highest();

	if (prio >= high)
		return high;
	if (prio < rtapi_prio_lowest())
		return rtapi_prio_lowest();
	return prio + 1;
}

int rtapi_prio_next_lower(int prio)
{
	int low = rtapi_prio_lowest();

	if (prio <= low)
		return low;
	if (prio > rtapi_prio_highest())
		return rtapi_prio_highest();
	return prio - 1;
}
