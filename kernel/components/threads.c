/* SPDX-License-Identifier: GPL-2.0-or-later */
/* threads.c - threads(9): create up to three realtime HAL threads from module
 * parameters: loadrt threads name1=NAME period1=NS [fp1=0|1] [name2=...] [name3=...].
 * Threads must be given in order, fastest first. The threads outlive the module:
 * it can be unloaded and loaded again to create more. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("creates hard realtime HAL threads");

#define THREADS_MAX 3

static char *name1;
RTAPI_MP_STRING(name1, "name of thread 1");
static long period1;
RTAPI_MP_LONG(period1, "period of thread 1 in nanoseconds");
static int fp1 = 1;
RTAPI_MP_INT(fp1, "thread 1 runs floating point functions (0 or 1, default 1)");
static char *name2;
RTAPI_MP_STRING(name2, "name of thread 2");
static long period2;
RTAPI_MP_LONG(period2, "period of thread 2 in nanoseconds");
static int fp2 = 1;
RTAPI_MP_INT(fp2, "thread 2 runs floating point functions (0 or 1, default 1)");
static char *name3;
RTAPI_MP_STRING(name3, "name of thread 3");
static long period3;
RTAPI_MP_LONG(period3, "period of thread 3 in nanoseconds");
static int fp3 = 1;
RTAPI_MP_INT(fp3, "thread 3 runs floating point functions (0 or 1, default 1)");

static int comp_id;

struct thread_spec {
	const char *name;	/* NULL or "" when not given */
	long period_ns;
	int fp;
};

static int given(const char *s)
{
	return s && s[0];
}

/* Check the parameters of thread k (1-based) against the page's rules. */
static int check_spec(const struct thread_spec *t, int k, long prev_period)
{
	if (!given(t->name)) {
		if (t->period_ns != 0) {
			rtapi_print_msg(RTAPI_MSG_ERR, "threads: period%d=%ld given without name%d\n",
					k, t->period_ns, k);
			return -EINVAL;
		}
		return 0;
	}
	if (t->period_ns <= 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, t->period_ns ?
				"threads: period%d=%ld for thread '%s' must be positive (nanoseconds)\n" :
				"threads: period%d=%ld: thread '%s' needs a period in nanoseconds\n",
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
				"threads: period%d=%ld is faster than period%d=%ld; threads must be given fastest first\n",
				k, t->period_ns, k - 1, prev_period);
		return -EINVAL;
	}
	return 0;
}

int rtapi_app_main(void)
{
	const struct thread_spec spec[THREADS_MAX] = {
		{ name1, period1, fp1 }, { name2, period2, fp2 }, { name3, period3, fp3 },
	};
	int n, k, err;

	/* Count the leading threads given; a later one after a gap is an error. */
	for (n = 0; n < THREADS_MAX && given(spec[n].name); n++)
		;
	if (n == 0) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"threads: name1= and period1= are required (loadrt threads name1=NAME period1=NS)\n");
		return -EINVAL;
	}
	for (k = 0; k < THREADS_MAX; k++) {
		if (k > n && given(spec[k].name)) {
			rtapi_print_msg(RTAPI_MSG_ERR, "threads: name%d= given without name%d=\n",
					k + 1, n + 1);
			return -EINVAL;
		}
		err = check_spec(&spec[k], k + 1, k > 0 && k < n ? spec[k - 1].period_ns : 0);
		if (err)
			return err;
	}
	comp_id = hal_init("threads");
	if (comp_id < 0)
		return comp_id;
	for (k = 0; k < n; k++) {
		err = hal_create_thread(spec[k].name, spec[k].period_ns, spec[k].fp);
		if (err < 0)
			goto undo_threads;
	}
	hal_ready(comp_id);
	return 0;

undo_threads:	/* hal_create_thread() logged why; remove the threads made before it */
	while (--k >= 0)
		hal_thread_delete(spec[k].name);
	hal_exit(comp_id);
	return err;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);	/* the threads stay: threads(9) says they stand alone */
}
