/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_time_kmod.c - clock, delays and the blocking mutex (rtapi_clock_set_period(3rtapi),
 * rtapi_delay(3rtapi), rtapi_get_time(3rtapi), rtapi_mutex(3rtapi)) in the kernel flavor. */
#include <linux/module.h>
#include <linux/delay.h>
#include <linux/ktime.h>
#include <linux/timex.h>
#include <linux/sched.h>
#include <linux/preempt.h>
#include "rtapi_kmod.h"

#define RTAPI_DELAY_MAX_NS 10000L	/* busy waits longer than this belong in a task period */
#define RTAPI_MIN_PERIOD_NS 1000L

static long clock_period;	/* ns; 0 until the first nonzero rtapi_clock_set_period */

long int rtapi_clock_set_period(long int nsec)
{
	long rc;

	if (nsec == 0)
		return READ_ONCE(clock_period);
	mutex_lock(&rtapi_kmod_lock);
	if (clock_period)
		rc = -EINVAL;	/* already running: the period is fixed until tasks are gone */
	else if (nsec < RTAPI_MIN_PERIOD_NS)
		rc = -EINVAL;
	else
		rc = clock_period = nsec;
	mutex_unlock(&rtapi_kmod_lock);
	return rc;
}
EXPORT_SYMBOL(rtapi_clock_set_period);

/* Called by the task code (lock held) when the last task is deleted. */
void rtapi_clock_reset(void)
{
	WRITE_ONCE(clock_period, 0);
}

void rtapi_delay(long int nsec)
{
	if (nsec <= 0)
		return;
	ndelay(min(nsec, RTAPI_DELAY_MAX_NS));
}
EXPORT_SYMBOL(rtapi_delay);

long int rtapi_delay_max(void)
{
	return RTAPI_DELAY_MAX_NS;
}
EXPORT_SYMBOL(rtapi_delay_max);

long long rtapi_get_time(void)
{
	return ktime_get_ns();
}
EXPORT_SYMBOL(rtapi_get_time);

long long rtapi_get_clocks(void)
{
	return (long long)get_cycles();
}
EXPORT_SYMBOL(rtapi_get_clocks);

void rtapi_sleep_ns(long long nsec)
{
	if (nsec <= 0)
		return;
	if (nsec >= 20 * NSEC_PER_MSEC) {
		msleep(div_u64(nsec, NSEC_PER_MSEC));
		return;
	}
	/* usleep_range for short sleeps: msleep would round up to a jiffy or more */
	usleep_range(div_u64(nsec, NSEC_PER_USEC) + 1, div_u64(nsec, NSEC_PER_USEC) + 50);
}
EXPORT_SYMBOL(rtapi_sleep_ns);

void rtapi_mutex_get(unsigned long *mutex)
{
	/* The holder may be a user process: sleep between tries, never spin forever. */
	while (rtapi_mutex_try(mutex))
		usleep_range(20, 100);
}
EXPORT_SYMBOL(rtapi_mutex_get);
