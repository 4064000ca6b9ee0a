/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_conformance.c - the documented behaviour of the RTAPI task calls
 * (rtapi_task_new(3rtapi), rtapi_task_start, rtapi_task_pause/rtapi_task_resume,
 * rtapi_task_wait, rtapi_prio), checked the same way in both flavors (see
 * rtapi_conformance.h). What the pages leave open is settled as the simulated flavor
 * always did, and the kernel flavor now does too:
 *   - a new task is paused and does not run;
 *   - rtapi_task_start(id, period) releases a paused task - new, or paused later -
 *     periodically (0); on a task that is not paused it is -EBUSY; a period of 0 or
 *     over 10 s is -EINVAL;
 *   - rtapi_task_resume(id) releases a paused task - a never-started one too - free-
 *     running (rtapi_task_wait only yields); on a task that is not paused, -EBUSY;
 *   - rtapi_task_pause pauses any task, running or not, the caller itself included;
 *   - an id that is not a task's is -EINVAL everywhere; rtapi_task_self is -EINVAL
 *     outside a task; a task cannot delete itself (-EDEADLK);
 *   - rtapi_prio_next_higher/lower stay within rtapi_prio_lowest..highest.
 * Waits poll with generous bounds (a TCG VM is slow): they decide that something
 * happens, never how fast; "does not run" is checked over 30 ms after settling.
 * Kernel flavor: this file is also the module; insmod runs the suite and fails with
 * -EINVAL if a case fails, each result in /proc/rtapi/messages. */
#include "rtapi.h"
#include "rtapi_conformance.h"

#define MS 1000000LL

struct counter {
	volatile long cycles;
	volatile int self;
	volatile int pause_now;		/* set by the test: the task pauses itself */
};

static void count_forever(void *arg)
{
	struct counter *c = arg;

	c->self = rtapi_task_self();
	for (;;) {
		c->cycles++;
		if (c->pause_now) {
			c->pause_now = 0;
			rtapi_task_pause(rtapi_task_self());
		}
		rtapi_task_wait();
	}
}

static void pause_self_each_cycle(void *arg)
{
	struct counter *c = arg;

	for (;;) {
		c->cycles++;
		rtapi_task_pause(rtapi_task_self());
		rtapi_task_wait();
	}
}

/* Polls until c->cycles >= n, at most ~4 s. */
static long wait_cycles(struct counter *c, long n)
{
	int i;

	for (i = 0; i < 4000 && c->cycles < n; i++)
		rtapi_sleep_ns(MS);
	return c->cycles;
}

/* Waits until the count stops changing (a cycle in flight ends), then returns it. */
static long settle(struct counter *c)
{
	long last;
	int i;

	for (i = 0; i < 100; i++) {
		last = c->cycles;
		rtapi_sleep_ns(10 * MS);
		if (c->cycles == last)
			return last;
	}
	return -1;
}

#define CHECK(cond)								\
	do {									\
		if (!(cond)) {							\
			rtapi_snprintf(why, why_len, "line %d: %s", __LINE__, #cond); \
			goto out;						\
		}								\
	} while (0)

/* uses_fp for every other task id: pausing and waiting inside an FPU section too */
static int new_task(void (*code)(void *), struct counter *c)
{
	static int n;

	c->cycles = 0;
	c->self = 0;
	c->pause_now = 0;
	return rtapi_task_new(code, c, rtapi_prio_highest(), 0, n++ & 1);
}

static int case_new_task_is_paused(char *why, int why_len)
{
	struct counter c;
	int id = new_task(count_forever, &c), rc = -1;

	CHECK(id > 0);
	rtapi_sleep_ns(30 * MS);
	CHECK(c.cycles == 0);
	rc = 0;
out:
	if (id > 0 && rtapi_task_delete(id) != 0 && rc == 0) {
		rtapi_snprintf(why, why_len, "deleting a never-started task failed");
		rc = -1;
	}
	return rc;
}

static int case_start_runs_periodically(char *why, int why_len)
{
	struct counter c;
	int id = new_task(count_forever, &c), rc = -1;

	CHECK(id > 0);
	CHECK(rtapi_task_start(id, 1000000) == 0);
	CHECK(wait_cycles(&c, 5) >= 5);
	CHECK(c.self == id);
	CHECK(rtapi_task_overruns(id) >= 0);
	CHECK(rtapi_task_start(id, 1000000) == -EBUSY);		/* running: pause first */
	CHECK(rtapi_task_resume(id) == -EBUSY);
	rc = 0;
out:
	if (id > 0)
		rtapi_task_delete(id);
	return rc;
}

static int case_start_after_pause(char *why, int why_len)
{
	struct counter c;
	long at;
	int id = new_task(count_forever, &c), rc = -1;

	CHECK(id > 0);
	CHECK(rtapi_task_start(id, 1000000) == 0);
	CHECK(wait_cycles(&c, 3) >= 3);
	CHECK(rtapi_task_pause(id) == 0);
	at = settle(&c);
	CHECK(at >= 3);
	rtapi_sleep_ns(30 * MS);
	CHECK(c.cycles == at);					/* paused: does not run */
	CHECK(rtapi_task_pause(id) == 0);			/* pausing a paused task: fine */
	CHECK(rtapi_task_start(id, 2000000) == 0);		/* a paused task starts again */
	CHECK(wait_cycles(&c, at + 3) >= at + 3);
	rc = 0;
out:
	if (id > 0)
		rtapi_task_delete(id);
	return rc;
}

/* Resumed, a task is free-running: with a period of 1 s before the pause, a hundred
 * cycles within the bound of wait_cycles could only come from having no period. */
static int case_resume_is_free_running(char *why, int why_len)
{
	struct counter c;
	long at;
	int id = new_task(count_forever, &c), rc = -1;

	CHECK(id > 0);
	CHECK(rtapi_task_start(id, 1000000000) == 0);
	CHECK(wait_cycles(&c, 1) >= 1);
	CHECK(rtapi_task_pause(id) == 0);
	at = settle(&c);
	CHECK(at >= 1);
	CHECK(rtapi_task_resume(id) == 0);
	CHECK(rtapi_task_resume(id) == -EBUSY);			/* not paused any more */
	CHECK(rtapi_task_start(id, 1000000) == -EBUSY);
	CHECK(wait_cycles(&c, at + 100) >= at + 100);
	c.pause_now = 1;					/* it pauses itself */
	at = settle(&c);
	CHECK(at > 0);
	rtapi_sleep_ns(30 * MS);
	CHECK(c.cycles == at);
	rc = 0;
out:
	if (id > 0)
		rtapi_task_delete(id);
	return rc;
}

static int case_resume_never_started(char *why, int why_len)
{
	struct counter c;
	long at;
	int id = new_task(count_forever, &c), rc = -1;

	CHECK(id > 0);
	CHECK(rtapi_task_resume(id) == 0);			/* paused since new: runs free */
	CHECK(wait_cycles(&c, 100) >= 100);
	c.pause_now = 1;
	at = settle(&c);
	CHECK(at >= 100);
	CHECK(rtapi_task_start(id, 1000000) == 0);		/* then periodic, after a pause */
	CHECK(wait_cycles(&c, at + 3) >= at + 3);
	rc = 0;
out:
	if (id > 0)
		rtapi_task_delete(id);
	return rc;
}

static int case_task_pauses_itself(char *why, int why_len)
{
	struct counter c;
	int id = new_task(pause_self_each_cycle, &c), rc = -1;

	CHECK(id > 0);
	CHECK(rtapi_task_start(id, 1000000) == 0);
	CHECK(wait_cycles(&c, 1) >= 1);
	CHECK(settle(&c) == 1);					/* stopped in rtapi_task_pause */
	CHECK(rtapi_task_start(id, 1000000) == 0);
	CHECK(wait_cycles(&c, 2) >= 2);
	CHECK(settle(&c) == 2);
	CHECK(rtapi_task_resume(id) == 0);
	CHECK(wait_cycles(&c, 3) >= 3);
	CHECK(settle(&c) == 3);
	rc = 0;
out:
	if (id > 0)
		rtapi_task_delete(id);
	return rc;
}

static int case_delete_stops_a_running_task(char *why, int why_len)
{
	struct counter c;
	long at;
	int id = new_task(count_forever, &c), rc = -1;

	CHECK(id > 0);
	CHECK(rtapi_task_start(id, 1000000) == 0);
	CHECK(wait_cycles(&c, 2) >= 2);
	CHECK(rtapi_task_delete(id) == 0);
	id = 0;
	at = c.cycles;
	rtapi_sleep_ns(30 * MS);
	CHECK(c.cycles == at);
	rc = 0;
out:
	if (id > 0)
		rtapi_task_delete(id);
	return rc;
}

static int case_bad_calls(char *why, int why_len)
{
	struct counter c;
	int id = 0, rc = -1;

	CHECK(rtapi_task_new(0, &c, rtapi_prio_highest(), 0, 0) == -EINVAL);
	CHECK(rtapi_task_new(count_forever, &c, rtapi_prio_highest() + 1, 0, 0) == -EINVAL);
	CHECK(rtapi_task_new(count_forever, &c, rtapi_prio_lowest() - 1, 0, 0) == -EINVAL);
	CHECK(rtapi_task_start(0, 1000000) == -EINVAL);
	CHECK(rtapi_task_start(9999, 1000000) == -EINVAL);
	CHECK(rtapi_task_resume(-1) == -EINVAL);
	CHECK(rtapi_task_pause(9999) == -EINVAL);
	CHECK(rtapi_task_delete(0) == -EINVAL);
	CHECK(rtapi_task_overruns(9999) == -EINVAL);
	CHECK(rtapi_task_self() == -EINVAL);			/* not called from a task */
	id = new_task(count_forever, &c);
	CHECK(id > 0);
	CHECK(rtapi_task_start(id, 0) == -EINVAL);
	CHECK(rtapi_task_start(id, 20000000000UL) == -EINVAL);	/* over 10 s (x86-64 only) */
	CHECK(rtapi_task_delete(id) == 0);
	CHECK(rtapi_task_delete(id) == -EINVAL);		/* gone */
	id = 0;
	rc = 0;
out:
	if (id > 0)
		rtapi_task_delete(id);
	return rc;
}

static int case_priorities(char *why, int why_len)
{
	int hi = rtapi_prio_highest(), lo = rtapi_prio_lowest(), rc = -1;

	CHECK(lo < hi);
	CHECK(rtapi_prio_next_higher(lo) == lo + 1);
	CHECK(rtapi_prio_next_lower(hi) == hi - 1);
	CHECK(rtapi_prio_next_higher(hi) == hi);
	CHECK(rtapi_prio_next_lower(lo) == lo);
	CHECK(rtapi_prio_next_higher(lo - 10) == lo);
	CHECK(rtapi_prio_next_lower(hi + 10) == hi);
	rc = 0;
out:
	return rc;
}

const struct rtapi_conf_case rtapi_conf_cases[] = {
	{ "new-task-is-paused", case_new_task_is_paused },
	{ "start-runs-periodically", case_start_runs_periodically },
	{ "start-after-pause", case_start_after_pause },
	{ "resume-is-free-running", case_resume_is_free_running },
	{ "resume-never-started", case_resume_never_started },
	{ "task-pauses-itself", case_task_pauses_itself },
	{ "delete-stops-a-running-task", case_delete_stops_a_running_task },
	{ "bad-calls", case_bad_calls },
	{ "priorities", case_priorities },
};
const int rtapi_conf_ncases = sizeof(rtapi_conf_cases) / sizeof(rtapi_conf_cases[0]);

#ifdef __KERNEL__
/* The kernel flavor: the suite runs at insmod; each result is one message. */
#include "rtapi_app.h"

MODULE_LICENSE("GPL");

int rtapi_app_main(void)
{
	char why[160];
	int i, failed = 0;

	for (i = 0; i < rtapi_conf_ncases; i++) {
		why[0] = '\0';
		if (rtapi_conf_cases[i].run(why, sizeof(why)) == 0) {
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi_conformance: PASS %s\n",
					rtapi_conf_cases[i].name);
		} else {
			failed++;
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi_conformance: FAIL %s: %s\n",
					rtapi_conf_cases[i].name, why);
		}
	}
	rtapi_print_msg(RTAPI_MSG_ERR, "rtapi_conformance: %d passed, %d failed\n",
			rtapi_conf_ncases - failed, failed);
	return failed ? -EINVAL : 0;
}

void rtapi_app_exit(void)
{
}
#endif
