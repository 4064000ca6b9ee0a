/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_task_uspace.c - realtime tasks (rtapi_task_new(3rtapi) and its pages) for the
 * simulated-realtime flavor, RTAPI build only: one POSIX thread per task, SCHED_FIFO
 * when the process may use it, periodic releases with clock_nanosleep(TIMER_ABSTIME).
 * A task that falls behind by whole periods counts them as overruns and skips them.
 * rtapi_task_delete sets a stop flag that the task sees in rtapi_task_wait(), where it
 * leaves through pthread_exit(); the deleter then joins it. So a task whose code is
 * "for (;;) { work(); rtapi_task_wait(); }" stops within one period.
 *
 * Lock-step mode (rtapi_task_lockstep(), HAL's setexact_for_test_suite_only): periodic
 * tasks run one at a time in virtual time, so test results repeat exactly. Each task
 * has a virtual next release; a token goes to the task with the earliest one (ties:
 * the higher priority, then the lower id), which sleeps until the matching wall-clock
 * time, runs one cycle and hands the token on in rtapi_task_wait(). Nothing is skipped
 * when late, and no overrun is counted. rtapi_task_lockstep_gate() lets the tasks
 * restart their schedule at one common instant when a gate opens (HAL's "start"),
 * so the first cycles after it are always in the same order. */
#include <pthread.h>
#include <sched.h>
#include <stdio.h>
#include <sys/mman.h>
#include <time.h>
#include "rtapi.h"

#define RTAPI_MAX_TASKS 64
#define RTAPI_TASK_MIN_STACK (256 * 1024)	/* kernel-sized stacks are too small here */
#define RTAPI_DELETE_WARN_S 2			/* say why rtapi_task_delete is waiting */

enum task_state { TASK_PAUSED, TASK_PERIODIC, TASK_FREERUN };

struct rtapi_task_rec {
	int in_use;			/* guarded by task_lock */
	pthread_t thread;
	void (*code)(void *);
	void *arg;
	int prio;
	int state;			/* enum task_state; atomic: written by start/pause/resume */
	int stop;			/* atomic: set once by rtapi_task_delete */
	int resync;			/* atomic: set by start/resume, cleared by the task */
	long period_ns;			/* written by rtapi_task_start before it sets state */
	long long next_ns;		/* next release; the task thread's own */
	long pll_correction_ns;		/* added to the next period once; the task thread's own */
	long long overruns;		/* atomic: written by the task thread */
	int lockstep;			/* the task thread's own: scheduled by the token */
	int in_sched;			/* guarded by ls_lock: waits for or holds the token */
	long long next_vt;		/* guarded by ls_lock: next release in virtual time */
	pthread_mutex_t lock;		/* with 'wake': only to sleep while paused */
	pthread_cond_t wake;
};

static pthread_mutex_t task_lock = PTHREAD_MUTEX_INITIALIZER;
static struct rtapi_task_rec tasks[RTAPI_MAX_TASKS + 1];	/* [0] unused: ids are 1.. */
static __thread struct rtapi_task_rec *current_task;
static int fifo_refused;	/* guarded by task_lock: warned once, normal scheduling since */

/* Lock-step scheduling, all guarded by ls_lock. */
#define LS_EXTERNAL ((struct rtapi_task_rec *)&ls_holder)	/* a non-task holds it */
static pthread_mutex_t ls_lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t ls_turn = PTHREAD_COND_INITIALIZER;
static int ls_on;			/* new periodic tasks join the lock step */
static struct rtapi_task_rec *ls_holder;	/* who runs now, or NULL */
static int ls_external_waiting;		/* rtapi_task_lockstep_sync() callers */
static long long ls_vnow;		/* virtual time of the last release */
static long long ls_origin_ns;		/* rtapi_get_time() at virtual time 0 */
static int ls_gate;			/* last value rtapi_task_lockstep_gate() saw */
static void ls_kick(void);
static void sleep_until(long long when_ns);

static struct rtapi_task_rec *task_get(int task_id, const char *what)
{
	struct rtapi_task_rec *t = NULL;

	pthread_mutex_lock(&task_lock);
	if (task_id >= 1 && task_id <= RTAPI_MAX_TASKS && tasks[task_id].in_use)
		t = &tasks[task_id];
	pthread_mutex_unlock(&task_lock);
	if (!t)
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: %s(%d): no such task\n", what, task_id);
	return t;
}

static int task_id_of(const struct rtapi_task_rec *t)
{
	return (int)(t - tasks);
}

static void set_state(struct rtapi_task_rec *t, int state)
{
	pthread_mutex_lock(&t->lock);
	__atomic_store_n(&t->resync, 1, __ATOMIC_RELAXED);
	__atomic_store_n(&t->state, state, __ATOMIC_RELEASE);
	pthread_cond_broadcast(&t->wake);
	pthread_mutex_unlock(&t->lock);
	ls_kick();
}

static int ls_scheduled_count(void)
{
	int i, n = 0;

	for (i = 1; i <= RTAPI_MAX_TASKS; i++)
		n += tasks[i].in_sched;
	return n;
}

/* Give a free token to whoever is next: a waiting rtapi_task_lockstep_sync() first,
 * then the task with the earliest virtual release. ls_lock held. */
static void ls_dispatch(void)
{
	struct rtapi_task_rec *best = NULL;
	int i;

	if (ls_holder)
		return;
	if (ls_external_waiting) {
		ls_holder = LS_EXTERNAL;
		pthread_cond_broadcast(&ls_turn);
		return;
	}
	for (i = 1; i <= RTAPI_MAX_TASKS; i++) {
		struct rtapi_task_rec *t = &tasks[i];

		if (!t->in_sched)
			continue;
		if (!best || t->next_vt < best->next_vt ||
		    (t->next_vt == best->next_vt && t->prio > best->prio))
			best = t;
	}
	if (best) {
		ls_holder = best;
		ls_vnow = best->next_vt;
		pthread_cond_broadcast(&ls_turn);
	}
}

/* The task leaves the schedule (paused, deleted), handing the token on. ls_lock held. */
static void ls_leave(struct rtapi_task_rec *t)
{
	t->in_sched = 0;
	if (ls_holder == t) {
		ls_holder = NULL;
		ls_dispatch();
	}
}

static void ls_leave_locking(struct rtapi_task_rec *t)
{
	if (!t->lockstep)
		return;
	pthread_mutex_lock(&ls_lock);
	ls_leave(t);
	pthread_mutex_unlock(&ls_lock);
}

/* Wake tasks waiting for the token so that they see a new state or stop flag. */
static void ls_kick(void)
{
	pthread_mutex_lock(&ls_lock);
	pthread_cond_broadcast(&ls_turn);
	pthread_mutex_unlock(&ls_lock);
}

/* Called by the task itself: block while paused; leave the thread when deleted. */
static void wait_while_paused(struct rtapi_task_rec *t)
{
	if (__atomic_load_n(&t->state, __ATOMIC_ACQUIRE) == TASK_PAUSED ||
	    __atomic_load_n(&t->stop, __ATOMIC_ACQUIRE)) {
		ls_leave_locking(t);
		pthread_mutex_lock(&t->lock);
		while (__atomic_load_n(&t->state, __ATOMIC_ACQUIRE) == TASK_PAUSED &&
		       !__atomic_load_n(&t->stop, __ATOMIC_ACQUIRE))
			pthread_cond_wait(&t->wake, &t->lock);
		pthread_mutex_unlock(&t->lock);
		if (__atomic_load_n(&t->stop, __ATOMIC_ACQUIRE))
			pthread_exit(NULL);
	}
}

static int ls_must_leave(struct rtapi_task_rec *t)
{
	return __atomic_load_n(&t->stop, __ATOMIC_ACQUIRE) ||
	       __atomic_load_n(&t->state, __ATOMIC_ACQUIRE) != TASK_PERIODIC;
}

/* Hand the token on and wait for the next turn: one period later in virtual time, or,
 * joining the schedule, at the first multiple of the period not before the virtual
 * present. Then sleep until that turn's wall-clock time. Returns -1 without the token,
 * out of the schedule, when the task is paused or deleted meanwhile. */
static int ls_next_turn(struct rtapi_task_rec *t)
{
	long long period = t->period_ns, release;

	pthread_mutex_lock(&ls_lock);
	if (t->in_sched) {
		t->next_vt += period;
	} else {
		if (!ls_holder && !ls_scheduled_count()) {	/* alone: a new origin */
			ls_vnow = 0;
			ls_gate = 0;
			ls_origin_ns = rtapi_get_time();
		}
		t->next_vt = (ls_vnow + period - 1) / period * period;
		t->in_sched = 1;
	}
	if (ls_holder == t)
		ls_holder = NULL;
	ls_dispatch();
	while (ls_holder != t && !ls_must_leave(t))
		pthread_cond_wait(&ls_turn, &ls_lock);
	if (ls_holder != t) {
		ls_leave(t);
		pthread_mutex_unlock(&ls_lock);
		return -1;
	}
	release = ls_origin_ns + t->next_vt;
	pthread_mutex_unlock(&ls_lock);
	t->next_ns = release;
	if (rtapi_get_time() < release)
		sleep_until(release);
	return 0;
}

/* rtapi_task_wait() of a lock-step task: returns holding the token, or free-running. */
static void ls_task_wait(struct rtapi_task_rec *t)
{
	for (;;) {
		wait_while_paused(t);		/* leaves the schedule first; exits if deleted */
		if (__atomic_load_n(&t->state, __ATOMIC_ACQUIRE) == TASK_FREERUN) {
			sched_yield();
			return;
		}
		__atomic_store_n(&t->resync, 0, __ATOMIC_RELAXED);
		if (ls_next_turn(t) == 0) {
			wait_while_paused(t);	/* paused or deleted while asleep */
			if (t->in_sched)
				return;
		}
	}
}

void rtapi_task_lockstep(int on)
{
	pthread_mutex_lock(&ls_lock);
	ls_on = on != 0;
	pthread_mutex_unlock(&ls_lock);
}

int rtapi_task_lockstep_gate(int value)
{
	struct rtapi_task_rec *t = current_task;
	int i;

	value = value != 0;
	if (!t || !t->lockstep || !t->in_sched)
		return value;
	pthread_mutex_lock(&ls_lock);
	if (value != ls_gate && ls_holder == t) {
		ls_gate = value;
		if (value) {	/* opened: everyone due now, the highest priority first */
			for (i = 1; i <= RTAPI_MAX_TASKS; i++)
				if (tasks[i].in_sched)
					tasks[i].next_vt = ls_vnow;
			ls_holder = NULL;
			ls_dispatch();
			while (ls_holder != t && !ls_must_leave(t))
				pthread_cond_wait(&ls_turn, &ls_lock);
			if (ls_holder != t) {
				ls_leave(t);	/* paused or deleted: rtapi_task_wait() sees it */
				value = 0;
			}
		}
	}
	pthread_mutex_unlock(&ls_lock);
	return value;
}

static void *task_main(void *arg)
{
	struct rtapi_task_rec *t = arg;
	char name[16];

	current_task = t;
	snprintf(name, sizeof(name), "rtapi-task%d", task_id_of(t));
	pthread_setname_np(pthread_self(), name);
	wait_while_paused(t);		/* created paused: start or resume releases it */
	__atomic_store_n(&t->resync, 0, __ATOMIC_RELAXED);
	t->next_ns = rtapi_get_time();
	pthread_mutex_lock(&ls_lock);
	t->lockstep = ls_on;
	pthread_mutex_unlock(&ls_lock);
	if (t->lockstep)
		ls_task_wait(t);	/* the first cycle waits for its turn too */
	t->code(t->arg);
	ls_leave_locking(t);
	return NULL;			/* the task code returned: the thread ends */
}

static void lock_memory_once(void)
{
	if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0)
		rtapi_print_msg(RTAPI_MSG_INFO, "rtapi: mlockall failed: memory is not locked, "
				"page faults may delay tasks\n");
}

/* Start the thread with SCHED_FIFO at prio; if the process may not, fall back to
 * normal scheduling for this and every later task, with one warning. */
static int create_thread(struct rtapi_task_rec *t, unsigned long stacksize)
{
	static pthread_once_t mlock_once = PTHREAD_ONCE_INIT;
	struct sched_param sp = { .sched_priority = t->prio };
	pthread_attr_t attr;
	int err = EPERM, refused;

	pthread_attr_init(&attr);
	pthread_attr_setstacksize(&attr, stacksize > RTAPI_TASK_MIN_STACK ? stacksize : RTAPI_TASK_MIN_STACK);
	pthread_mutex_lock(&task_lock);
	refused = fifo_refused;
	pthread_mutex_unlock(&task_lock);
	if (!refused) {
		pthread_attr_setinheritsched(&attr, PTHREAD_EXPLICIT_SCHED);
		pthread_attr_setschedpolicy(&attr, SCHED_FIFO);
		pthread_attr_setschedparam(&attr, &sp);
		err = pthread_create(&t->thread, &attr, task_main, t);
		if (err == 0)
			pthread_once(&mlock_once, lock_memory_once);
	}
	if (err == EPERM) {
		pthread_mutex_lock(&task_lock);
		if (!fifo_refused)
			rtapi_print_msg(RTAPI_MSG_WARN, "rtapi: SCHED_FIFO not permitted (needs root, "
					"CAP_SYS_NICE or an rtprio limit): tasks run with normal "
					"scheduling and poor timing\n");
		fifo_refused = 1;
		pthread_mutex_unlock(&task_lock);
		pthread_attr_setinheritsched(&attr, PTHREAD_INHERIT_SCHED);
		err = pthread_create(&t->thread, &attr, task_main, t);
	}
	pthread_attr_destroy(&attr);
	return err;
}

int rtapi_task_new(void (*taskcode)(void *), void *arg, int prio,
		   unsigned long stacksize, int uses_fp)
{
	struct rtapi_task_rec *t = NULL;
	int id, err;

	if (!taskcode) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_new: no task code\n");
		return -EINVAL;
	}
	if (prio < rtapi_prio_lowest() || prio > rtapi_prio_highest()) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_new: priority %d outside %d..%d\n",
				prio, rtapi_prio_lowest(), rtapi_prio_highest());
		return -EINVAL;
	}
	pthread_mutex_lock(&task_lock);
	for (id = 1; id <= RTAPI_MAX_TASKS; id++) {
		if (!tasks[id].in_use) {
			t = &tasks[id];
			t->in_use = 1;
			break;
		}
	}
	pthread_mutex_unlock(&task_lock);
	if (!t) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_new: all %d tasks in use\n",
				RTAPI_MAX_TASKS);
		return -ENOMEM;
	}
	t->code = taskcode;
	t->arg = arg;
	t->prio = prio;
	t->state = TASK_PAUSED;
	t->stop = 0;
	t->resync = 0;
	t->period_ns = 0;
	t->pll_correction_ns = 0;
	t->overruns = 0;
	t->lockstep = 0;
	t->in_sched = 0;
	pthread_mutex_init(&t->lock, NULL);
	pthread_cond_init(&t->wake, NULL);
	err = create_thread(t, stacksize);	/* uses_fp: threads always have the FPU here */
	if (err) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_new: cannot create a thread: %s\n",
				err == EAGAIN ? "out of resources" : "pthread_create failed");
		pthread_cond_destroy(&t->wake);
		pthread_mutex_destroy(&t->lock);
		pthread_mutex_lock(&task_lock);
		t->in_use = 0;
		pthread_mutex_unlock(&task_lock);
		return -err;
	}
	return id;
}

int rtapi_task_delete(int task_id)
{
	struct rtapi_task_rec *t = task_get(task_id, "rtapi_task_delete");
	struct timespec limit;

	if (!t)
		return -EINVAL;
	if (t == current_task) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_delete(%d): a task cannot delete "
				"itself\n", task_id);
		return -EDEADLK;
	}
	pthread_mutex_lock(&t->lock);
	__atomic_store_n(&t->stop, 1, __ATOMIC_RELEASE);
	pthread_cond_broadcast(&t->wake);
	pthread_mutex_unlock(&t->lock);
	ls_kick();
	clock_gettime(CLOCK_REALTIME, &limit);
	limit.tv_sec += RTAPI_DELETE_WARN_S;
	if (pthread_timedjoin_np(t->thread, NULL, &limit) != 0) {
		rtapi_print_msg(RTAPI_MSG_WARN, "rtapi: waiting for task %d to stop: its code must "
				"call rtapi_task_wait() or return\n", task_id);
		pthread_join(t->thread, NULL);
	}
	pthread_cond_destroy(&t->wake);
	pthread_mutex_destroy(&t->lock);
	pthread_mutex_lock(&task_lock);
	t->in_use = 0;
	pthread_mutex_unlock(&task_lock);
	return 0;
}

int rtapi_task_start(int task_id, unsigned long int period_nsec)
{
	struct rtapi_task_rec *t = task_get(task_id, "rtapi_task_start");
	long clock = rtapi_clock_set_period(0);

	if (!t)
		return -EINVAL;
	if (period_nsec == 0 || period_nsec > 10000000000UL) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_start(%d): period %lu ns is not "
				"1..10000000000\n", task_id, period_nsec);
		return -EINVAL;
	}
	if (__atomic_load_n(&t->state, __ATOMIC_ACQUIRE) != TASK_PAUSED) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_start(%d): the task is running, "
				"pause it first\n", task_id);
		return -EBUSY;
	}
	if (clock > 0 && (long)period_nsec < clock)
		period_nsec = (unsigned long)clock;	/* nothing runs faster than the clock */
	t->period_ns = (long)period_nsec;
	set_state(t, TASK_PERIODIC);
	return 0;
}

int rtapi_task_resume(int task_id)
{
	struct rtapi_task_rec *t = task_get(task_id, "rtapi_task_resume");

	if (!t)
		return -EINVAL;
	if (__atomic_load_n(&t->state, __ATOMIC_ACQUIRE) != TASK_PAUSED) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_resume(%d): the task is not "
				"paused\n", task_id);
		return -EBUSY;
	}
	set_state(t, TASK_FREERUN);
	return 0;
}

int rtapi_task_pause(int task_id)
{
	struct rtapi_task_rec *t = task_get(task_id, "rtapi_task_pause");

	if (!t)
		return -EINVAL;
	set_state(t, TASK_PAUSED);
	if (t == current_task)		/* pausing itself: stop right here */
		wait_while_paused(t);
	return 0;
}

int rtapi_task_self(void)
{
	return current_task ? task_id_of(current_task) : -EINVAL;
}

long long rtapi_task_overruns(int task_id)
{
	struct rtapi_task_rec *t = task_get(task_id, "rtapi_task_overruns");

	if (!t)
		return -EINVAL;
	return __atomic_load_n(&t->overruns, __ATOMIC_RELAXED);
}

long long rtapi_task_pll_get_reference(void)
{
	return current_task ? current_task->next_ns : 0;
}

int rtapi_task_pll_set_correction(long value)
{
	struct rtapi_task_rec *t = current_task;

	if (!t || t->period_ns <= 0)
		return -EINVAL;
	if (value > t->period_ns / 10 || value < -(t->period_ns / 10))
		return -EINVAL;
	t->pll_correction_ns = value;
	return 0;
}

static void sleep_until(long long when_ns)
{
	struct timespec ts = { .tv_sec = when_ns / 1000000000LL, .tv_nsec = when_ns % 1000000000LL };

	while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) == EINTR)
		;
}

void rtapi_task_wait(void)
{
	struct rtapi_task_rec *t = current_task;
	long long now, late;
	long period;

	if (!t) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_wait called outside a task\n");
		return;
	}
	if (t->lockstep) {
		ls_task_wait(t);
		return;
	}
	wait_while_paused(t);
	if (__atomic_exchange_n(&t->resync, 0, __ATOMIC_ACQ_REL)) {
		t->next_ns = rtapi_get_time();	/* (re)started: this is the first release */
		return;
	}
	if (__atomic_load_n(&t->state, __ATOMIC_ACQUIRE) != TASK_PERIODIC) {
		sched_yield();			/* free-running: nothing to wait for */
		return;
	}
	period = t->period_ns;
	t->next_ns += period + t->pll_correction_ns;
	t->pll_correction_ns = 0;
	now = rtapi_get_time();
	late = now - t->next_ns;
	if (late >= period) {		/* whole periods missed: count and skip them */
		long long missed = late / period;

		__atomic_add_fetch(&t->overruns, missed, __ATOMIC_RELAXED);
		t->next_ns += missed * period;
	}
	if (now < t->next_ns)
		sleep_until(t->next_ns);
	wait_while_paused(t);		/* deleted or paused while asleep */
	if (__atomic_exchange_n(&t->resync, 0, __ATOMIC_ACQ_REL))
		t->next_ns = rtapi_get_time();
}

void rtapi_wait(void)
{
	rtapi_task_wait();
}
