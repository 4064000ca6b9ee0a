/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_task_kmod.c - realtime tasks (rtapi_task_new(3rtapi) and friends) as
 * SCHED_FIFO kernel threads waiting on absolute hrtimers. A task that uses floating
 * point runs each period's work inside kernel_fpu_begin/end: the section opens before
 * the task code first runs and after every wake-up, and closes before every sleep.
 * States and return codes are those of the simulated flavor (rtapi_task_uspace.c),
 * as the rtapi_task pages describe them; tests/rtapi_conformance runs the same suite
 * against both: a new task is paused; rtapi_task_start makes a paused task (new or
 * paused later) periodic, rtapi_task_resume makes it free-running (rtapi_task_wait
 * then only yields), either on a task that is not paused is -EBUSY; rtapi_task_pause
 * pauses any task, the caller itself included (it stops right there). */
#include <linux/module.h>
#include <linux/kthread.h>
#include <linux/sched.h>
#include <linux/hrtimer.h>
#include <linux/ktime.h>
#include <linux/seq_file.h>
#include <linux/math64.h>
#include <uapi/linux/sched/types.h>
#include <asm/fpu/api.h>
#include "rtapi_kmod.h"

#define PRIO_LOWEST 1
#define PRIO_HIGHEST 98		/* 99 is left for the kernel's own watchdogs */

enum task_state { TASK_PAUSED, TASK_PERIODIC, TASK_FREERUN };

struct rtapi_task {
	bool used;
	bool released;			/* started or resumed at least once (for the table) */
	int state;			/* enum task_state; written under rtapi_kmod_lock */
	int resync;			/* set by start/resume: the next wait is a first release */
	int uses_fp;
	int prio;
	void (*code)(void *);
	void *arg;
	struct task_struct *thread;
	u64 period_ns;
	ktime_t next;			/* absolute deadline of the next release */
	atomic64_t overruns;		/* periods missed since start */
	atomic64_t cycles;		/* wake-ups since start */
};

static struct rtapi_task tasks[RTAPI_MAX_TASKS];	/* index 0 unused: ids are > 0 */

int rtapi_prio_highest(void) { return PRIO_HIGHEST; }
EXPORT_SYMBOL(rtapi_prio_highest);
int rtapi_prio_lowest(void) { return PRIO_LOWEST; }
EXPORT_SYMBOL(rtapi_prio_lowest);
/* Out-of-range arguments come back in range, as in the simulated flavor. */
int rtapi_prio_next_higher(int prio)
{
	return prio >= PRIO_HIGHEST ? PRIO_HIGHEST : prio < PRIO_LOWEST ? PRIO_LOWEST : prio + 1;
}
EXPORT_SYMBOL(rtapi_prio_next_higher);
int rtapi_prio_next_lower(int prio)
{
	return prio <= PRIO_LOWEST ? PRIO_LOWEST : prio > PRIO_HIGHEST ? PRIO_HIGHEST : prio - 1;
}
EXPORT_SYMBOL(rtapi_prio_next_lower);

static struct rtapi_task *task_of_current(void)
{
	int i;

	for (i = 1; i < RTAPI_MAX_TASKS; i++)
		if (tasks[i].used && tasks[i].thread == current)
			return &tasks[i];
	return NULL;
}

static struct rtapi_task *task_by_id(int id)	/* lock held */
{
	if (id <= 0 || id >= RTAPI_MAX_TASKS || !tasks[id].used)
		return NULL;
	return &tasks[id];
}

/* Sleeps while the task is paused (outside any FPU section); leaves the thread for
 * good when rtapi_task_delete asked it to stop. */
static void wait_while_paused(struct rtapi_task *t)
{
	for (;;) {
		set_current_state(TASK_IDLE);
		if (kthread_should_stop()) {
			__set_current_state(TASK_RUNNING);
			kthread_complete_and_exit(NULL, 0);
		}
		if (READ_ONCE(t->state) != TASK_PAUSED)
			break;
		schedule();
	}
	__set_current_state(TASK_RUNNING);
}

static int task_thread(void *data)
{
	struct rtapi_task *t = data;

	wait_while_paused(t);	/* created paused: start or resume releases it */
	xchg(&t->resync, 0);
	t->next = ktime_get();
	if (t->uses_fp)
		kernel_fpu_begin();
	t->code(t->arg);
	if (t->uses_fp)
		kernel_fpu_end();
	/* The task code returned: idle until rtapi_task_delete stops this thread. */
	for (;;) {
		set_current_state(TASK_IDLE);
		if (kthread_should_stop())
			break;
		schedule();
	}
	__set_current_state(TASK_RUNNING);
	return 0;
}

/* Sleeps until the next release, and leaves the thread for good when rtapi_task_delete
 * asked it to stop: the task code's loop never ends by itself. A paused task sleeps
 * until start or resume; the first wait after those returns at once (the first
 * release); a free-running task only gives way to others. */
static void task_sleep(struct rtapi_task *t)
{
	bool advanced = false;

	for (;;) {
		int state;

		set_current_state(TASK_IDLE);
		if (kthread_should_stop()) {
			__set_current_state(TASK_RUNNING);
			kthread_complete_and_exit(NULL, 0);
		}
		state = READ_ONCE(t->state);
		if (state == TASK_PAUSED) {
			schedule();
			continue;
		}
		if (xchg(&t->resync, 0)) {	/* (re)started: this is the first release */
			t->next = ktime_get();
			break;
		}
		if (state == TASK_FREERUN) {
			__set_current_state(TASK_RUNNING);
			cond_resched();
			break;
		}
		if (!advanced) {
			ktime_t now = ktime_get();

			advanced = true;
			t->next = ktime_add_ns(t->next, t->period_ns);
			if (ktime_before(t->next, now)) {
				/* Late: count the releases missed and resume the grid after now. */
				u64 missed = div64_u64(ktime_to_ns(ktime_sub(now, t->next)), t->period_ns) + 1;

				atomic64_add(missed, &t->overruns);
				t->next = ktime_add_ns(t->next, missed * t->period_ns);
			}
		}
		if (schedule_hrtimeout_range_clock(&t->next, 0, HRTIMER_MODE_ABS,
						   CLOCK_MONOTONIC) == 0 ||
		    ktime_before(t->next, ktime_get())) {
			/* our release, unless paused meanwhile: then not before start/resume */
			if (READ_ONCE(t->state) == TASK_PERIODIC && !READ_ONCE(t->resync))
				break;
		}
		/* woken early (stop, pause, start or resume): look again */
	}
	__set_current_state(TASK_RUNNING);
	atomic64_inc(&t->cycles);
}

void rtapi_task_wait(void)
{
	struct rtapi_task *t = task_of_current();

	if (!t) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi_task_wait: not called from an RTAPI task\n");
		return;
	}
	if (t->uses_fp)
		kernel_fpu_end();
	task_sleep(t);
	if (t->uses_fp)
		kernel_fpu_begin();
}
EXPORT_SYMBOL(rtapi_task_wait);

void rtapi_wait(void)
{
	rtapi_task_wait();
}
EXPORT_SYMBOL(rtapi_wait);

int rtapi_task_new(void (*taskcode)(void *), void *arg, int prio,
		   unsigned long stacksize, int uses_fp)
{
	struct sched_attr attr = { .size = sizeof(attr), .sched_policy = SCHED_FIFO };
	struct task_struct *thread;
	struct rtapi_task *t;
	int id, rc;

	if (!taskcode || prio < PRIO_LOWEST || prio > PRIO_HIGHEST) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi_task_new: priority %d outside %d..%d\n",
				prio, PRIO_LOWEST, PRIO_HIGHEST);
		return -EINVAL;
	}
	mutex_lock(&rtapi_kmod_lock);
	for (id = 1; id < RTAPI_MAX_TASKS && tasks[id].used; id++)
		;
	if (id == RTAPI_MAX_TASKS) {
		mutex_unlock(&rtapi_kmod_lock);
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi_task_new: all %d task slots in use\n",
				RTAPI_MAX_TASKS - 1);
		return -ENOMEM;
	}
	t = &tasks[id];
	memset(t, 0, sizeof(*t));
	t->code = taskcode;
	t->arg = arg;
	t->prio = prio;
	t->uses_fp = uses_fp;
	thread = kthread_create(task_thread, t, "rtapi:%d", id);
	if (IS_ERR(thread)) {
		mutex_unlock(&rtapi_kmod_lock);
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi_task_new: cannot create a thread (%ld)\n",
				PTR_ERR(thread));
		return PTR_ERR(thread);
	}
	/* Before the first wait: on PREEMPT_RT the timer then fires in hard-irq context. */
	attr.sched_priority = prio;
	rc = sched_setattr_nocheck(thread, &attr);
	if (rc) {
		kthread_stop(thread);
		mutex_unlock(&rtapi_kmod_lock);
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi_task_new: cannot set SCHED_FIFO %d (%d)\n",
				prio, rc);
		return rc;
	}
	t->thread = thread;
	t->used = true;
	mutex_unlock(&rtapi_kmod_lock);
	return id;
}
EXPORT_SYMBOL(rtapi_task_new);

int rtapi_task_delete(int task_id)
{
	struct task_struct *thread;
	struct rtapi_task *t;
	int i, left = 0;

	mutex_lock(&rtapi_kmod_lock);
	t = task_by_id(task_id);
	if (!t) {
		mutex_unlock(&rtapi_kmod_lock);
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_delete(%d): no such task\n", task_id);
		return -EINVAL;
	}
	if (t->thread == current) {
		mutex_unlock(&rtapi_kmod_lock);
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_delete(%d): a task cannot delete "
				"itself\n", task_id);
		return -EDEADLK;
	}
	thread = t->thread;
	mutex_unlock(&rtapi_kmod_lock);
	kthread_stop(thread);	/* returns once the thread has left its code for good */
	mutex_lock(&rtapi_kmod_lock);
	t->used = false;
	t->thread = NULL;
	for (i = 1; i < RTAPI_MAX_TASKS; i++)
		left += tasks[i].used;
	if (!left)
		rtapi_clock_reset();
	mutex_unlock(&rtapi_kmod_lock);
	return 0;
}
EXPORT_SYMBOL(rtapi_task_delete);

/* Releases a paused task into 'state' (lock held). */
static void release(struct rtapi_task *t, int state)
{
	t->released = true;
	WRITE_ONCE(t->resync, 1);
	WRITE_ONCE(t->state, state);
	wake_up_process(t->thread);
}

int rtapi_task_start(int task_id, unsigned long int period_nsec)
{
	long clock = rtapi_clock_set_period(0);
	struct rtapi_task *t;
	int rc = 0;

	mutex_lock(&rtapi_kmod_lock);
	t = task_by_id(task_id);
	if (!t) {
		rc = -EINVAL;
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_start(%d): no such task\n", task_id);
	} else if (period_nsec == 0 || period_nsec > 10000000000UL) {
		rc = -EINVAL;
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_start(%d): period %lu ns is not "
				"1..10000000000\n", task_id, period_nsec);
	} else if (READ_ONCE(t->state) != TASK_PAUSED) {
		rc = -EBUSY;
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_start(%d): the task is running, "
				"pause it first\n", task_id);
	} else {
		if (clock > 0 && (long)period_nsec < clock)
			period_nsec = (unsigned long)clock;	/* nothing runs faster than the clock */
		t->period_ns = period_nsec;
		release(t, TASK_PERIODIC);
	}
	mutex_unlock(&rtapi_kmod_lock);
	return rc;
}
EXPORT_SYMBOL(rtapi_task_start);

int rtapi_task_resume(int task_id)
{
	struct rtapi_task *t;
	int rc = 0;

	mutex_lock(&rtapi_kmod_lock);
	t = task_by_id(task_id);
	if (!t) {
		rc = -EINVAL;
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_resume(%d): no such task\n", task_id);
	} else if (READ_ONCE(t->state) != TASK_PAUSED) {
		rc = -EBUSY;
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_resume(%d): the task is not "
				"paused\n", task_id);
	} else {
		release(t, TASK_FREERUN);
	}
	mutex_unlock(&rtapi_kmod_lock);
	return rc;
}
EXPORT_SYMBOL(rtapi_task_resume);

/* May be called by the task itself, inside its FPU section: it then stops here until
 * start or resume (the next rtapi_task_wait is that release's first). The section is
 * closed before anything that may sleep: the lock below is a sleeping lock on
 * PREEMPT_RT, and kernel_fpu_begin disables preemption. */
int rtapi_task_pause(int task_id)
{
	struct rtapi_task *t, *self = task_of_current();
	bool fpu = self && self->uses_fp && (int)(self - tasks) == task_id;

	if (fpu)
		kernel_fpu_end();
	mutex_lock(&rtapi_kmod_lock);
	t = task_by_id(task_id);
	if (t)
		WRITE_ONCE(t->state, TASK_PAUSED);
	mutex_unlock(&rtapi_kmod_lock);
	if (!t)
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_task_pause(%d): no such task\n", task_id);
	else if (t->thread == current)
		wait_while_paused(t);
	if (fpu)
		kernel_fpu_begin();
	return t ? 0 : -EINVAL;
}
EXPORT_SYMBOL(rtapi_task_pause);

int rtapi_task_self(void)
{
	struct rtapi_task *t = task_of_current();

	return t ? (int)(t - tasks) : -EINVAL;
}
EXPORT_SYMBOL(rtapi_task_self);

long long rtapi_task_overruns(int task_id)
{
	if (task_id <= 0 || task_id >= RTAPI_MAX_TASKS || !READ_ONCE(tasks[task_id].used))
		return -EINVAL;
	return atomic64_read(&tasks[task_id].overruns);
}
EXPORT_SYMBOL(rtapi_task_overruns);

void rtapi_task_show(struct seq_file *m)
{
	int id;

	mutex_lock(&rtapi_kmod_lock);
	seq_puts(m, "ID  PID     PRIO FP PERIOD_NS    STATE   CYCLES       OVERRUNS\n");
	for (id = 1; id < RTAPI_MAX_TASKS; id++) {
		struct rtapi_task *t = &tasks[id];

		if (!t->used)
			continue;
		seq_printf(m, "%-3d %-7d %-4d %-2d %-12llu %-7s %-12lld %lld\n", id,
			   task_pid_nr(t->thread), t->prio, t->uses_fp ? 1 : 0, t->period_ns,
			   !t->released ? "new" :
			   READ_ONCE(t->state) == TASK_PAUSED ? "paused" :
			   READ_ONCE(t->state) == TASK_FREERUN ? "freerun" : "running",
			   (long long)atomic64_read(&t->cycles),
			   (long long)atomic64_read(&t->overruns));
	}
	seq_printf(m, "clock period: %ld ns\n", rtapi_clock_set_period(0));
	mutex_unlock(&rtapi_kmod_lock);
}

void rtapi_task_kmod_exit(void)
{
	int id;

	for (id = 1; id < RTAPI_MAX_TASKS; id++) {
		if (!tasks[id].used)
			continue;
		printk(KERN_ERR "RTAPI: task %d was never deleted: stopping it\n", id);
		rtapi_task_delete(id);
	}
}

/* FPU sections for init/exit code (rtapi.h); the kernel's own calls are GPL-only
 * inline wrappers, so components reach them through these. */
void rtapi_fpu_begin(void)
{
	kernel_fpu_begin();
}
EXPORT_SYMBOL(rtapi_fpu_begin);

void rtapi_fpu_end(void)
{
	kernel_fpu_end();
}
EXPORT_SYMBOL(rtapi_fpu_end);
