/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_time_uspace.c - clock period, time stamps, delays and sleeping
 * (rtapi_clock_set_period(3rtapi), rtapi_get_time(3rtapi), rtapi_delay(3rtapi)) for the
 * simulated-realtime flavor, on CLOCK_MONOTONIC. */
#include <time.h>
#include "rtapi.h"

#define RTAPI_MIN_PERIOD_NS 1000L		/* 1 us: shorter periods are refused */
#define RTAPI_MAX_PERIOD_NS 10000000000L	/* 10 s */
#define RTAPI_DELAY_MAX_NO_PERIOD_NS 10000L	/* rtapi_delay_max() before the clock runs */

static long clock_period_ns;	/* 0 until the first successful rtapi_clock_set_period */

static inline void cpu_relax(void)
{
#if defined(__x86_64__) || defined(__i386__)
	__builtin_ia32_pause();
#endif
}

long int rtapi_clock_set_period(long int nsec)
{
	long expected = 0;

	if (nsec == 0)
		return __atomic_load_n(&clock_period_ns, __ATOMIC_ACQUIRE);
	if (nsec < RTAPI_MIN_PERIOD_NS || nsec > RTAPI_MAX_PERIOD_NS) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: clock period %ld ns refused: must be %ld..%ld ns\n",
				nsec, RTAPI_MIN_PERIOD_NS, RTAPI_MAX_PERIOD_NS);
		return -EINVAL;
	}
	if (!__atomic_compare_exchange_n(&clock_period_ns, &expected, nsec, 0,
					 __ATOMIC_ACQ_REL, __ATOMIC_ACQUIRE)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: clock period %ld ns refused: the clock already "
				"runs with %ld ns\n", nsec, expected);
		return -EINVAL;
	}
	return nsec;
}

long long rtapi_get_time(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

long long rtapi_get_clocks(void)
{
#if defined(__x86_64__) || defined(__i386__)
	return (long long)__builtin_ia32_rdtsc();
#else
	return rtapi_get_time();
#endif
}

/* A quarter of the clock period, as rtapi_delay(3rtapi) suggests; 10 us before the
 * clock is started. */
long int rtapi_delay_max(void)
{
	long period = rtapi_clock_set_period(0);

	return period ? period / 4 : RTAPI_DELAY_MAX_NO_PERIOD_NS;
}

void rtapi_delay(long int nsec)
{
	long long end;
	long max = rtapi_delay_max();

	if (nsec > max)
		nsec = max;
	if (nsec <= 0)
		return;
	end = rtapi_get_time() + nsec;
	while (rtapi_get_time() < end)
		cpu_relax();
}

void rtapi_sleep_ns(long long nsec)
{
	struct timespec ts;
	long long until;

	if (nsec <= 0)
		return;
	until = rtapi_get_time() + nsec;
	ts.tv_sec = until / 1000000000LL;
	ts.tv_nsec = until % 1000000000LL;
	while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) == EINTR)
		;
}
