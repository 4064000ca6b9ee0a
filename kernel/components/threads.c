/* SPDX-License-Identifier: GPL-2.0-or-later */
/* threads.c - threads(9): create up to three realtime HAL threads from module
 * parameters: loadrt threads [name1=NAME] [period1=NS] [fp1=0|1] [name2=...] [name3=...].
 * Defaults as in LinuxCNC: nameK is "threadK", period1 is 1 ms, period2/period3 are 0
 * (no such thread), fpK is 1; so "loadrt threads" alone makes thread1 at 1 ms. Threads
 * with a period are created fastest first. The threads outlive the module: it can be
 * unloaded and loaded again to create more. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("creates hard realtime HAL threads");

#define THREADS_MAX 3

static char *name1;
RTAPI_MP_STRING(name1, "name of thread 1");
static long period1 = 1000000;
RTAPI_MP_LONG(period1, "period of thread 1 in nanoseconds (default 1000000)");
static int fp1 = 1;
RTAPI_MP_INT(fp1, "thread 1 runs floating point functions (0 or 1, default 1)");
static char *name2;
RTAPI_MP_STRING(name2, "name of thread 2");
static long period2;
RTAPI_MP_LONG(period2, "period of thread 2 in nanoseconds (default 0: no thread 2)");
static int fp2 = 1;
RTAPI_MP_INT(fp2, "thread 2 runs floating point functions (0 or 1, default 1)");
static char *name3;
RTAPI_MP_STRING(name3, "name of thread 3");
static long period3;
RTAPI_MP_LONG(period3, "period of thread 3 in nanoseconds (default 0: no thread 3)");
static int fp3 = 1;
RTAPI_MP_INT(fp3, "thread 3 runs floating point functions (0 or 1, default 1)");

static int comp_id;

struct thread_spec {
	const char *name;	/* the given name, or "threadK" */
	long period_ns;		/* 0: no such thread */
	int fp;
	int name_given;
};

static int given(const char *s)
{
	return s && s[0];
}

/* Check the parameters of thread k (1-based); prev_period is the period of the last
 * thread before it that will be created, 0 if none. */
static int check_spec(const struct thread_spec *t, int k, long prev_period)
{
	if (t->period_ns == 0) {
		if (t->name_given) {
			rtapi_print_msg(RTAPI_MSG_ERR, "threads: name%d=%s given without period%d\n",
					k, t->name, k);
			return -EINVAL;
		}
		return 0;
	}
	if (t->period_ns < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"threads: period%d=%ld for thread '%s' must be positive (nanoseconds)\n",
				k, t->period_ns, t->name);
		return -EINVAL;
	}
	if (t->fp != 0 && t->fp != 1) {
		rtapi_print_msg(RTAPI_MSG_ERR, "threads: fp%d=%d for thread '%s' must be 0 or 1\n",
				k, t->fp, t->name);
		return -EINVAL;
	}
	if (prev_period > t->period_ns) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"threads: period%d=%ld is faster than the thread before it (%ld); "
				"threads must be given fastest first\n", k, t->period_ns, prev_period);
		return -EINVAL;
	}
	return 0;
}

int rtapi_app_main(void)
{
	const struct thread_spec spec[THREADS_MAX] = {
		{ given(name1) ? name1 : "thread1", period1, fp1, given(name1) },
		{ given(name2) ? name2 : "thread2", period2, fp2, given(name2) },
		{ given(name3) ? name3 : "thread3", period3, fp3, given(name3) },
	};
	long prev = 0;
	int k, err;

	for (k = 0; k < THREADS_MAX; k++) {
		err = check_spec(&spec[k], k + 1, prev);
		if (err)
			return err;
		if (spec[k].period_ns > 0)
			prev = spec[k].period_ns;
	}
	if (prev == 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "threads: period1=0 and no other period: no thread to create\n");
		return -EINVAL;
	}
	comp_id = hal_init("threads");
	if (comp_id < 0)
		return comp_id;
	for (k = 0; k < THREADS_MAX; k++) {
		if (spec[k].period_ns == 0)
			continue;
		err = hal_create_thread(spec[k].name, spec[k].period_ns, spec[k].fp);
		if (err < 0)
			goto undo_threads;
	}
	hal_ready(comp_id);
	return 0;

undo_threads:	/* hal_create_thread() logged why; remove the threads made before it */
	while (--k >= 0)
		if (spec[k].period_ns != 0)
			hal_thread_delete(spec[k].name);
	hal_exit(comp_id);
	return err;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);	/* the threads stay: threads(9) says they stand alone */
}
