/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_mutex_uspace.c - the blocking rtapi_mutex_get (rtapi_mutex(3rtapi)); try and give
 * are inline in rtapi.h. The word may be shared with other processes, so this spins
 * with sched_yield() rather than using a futex the kernel flavor could not share. */
#include <sched.h>
#include "rtapi.h"

void rtapi_mutex_get(unsigned long *mutex)
{
	while (rtapi_mutex_try(mutex))
		sched_yield();
}
