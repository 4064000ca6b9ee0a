/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_thread.c - HAL threads (hal_create_thread(3hal)): an RTAPI periodic task
 * that calls its functions in order each period while threads are started.
 * Threads are created by realtime code only; halcmd edits their function lists
 * from userspace, which the task walks without taking the HAL mutex.
 * As threads(9) says, a thread stands alone once created: it belongs to the
 * realtime host (owner 0), survives unloading the module that made it, and goes
 * with hal_thread_delete() or hal_exit_threads() when the host shuts down. */
#include "hal_internal.h"

#ifdef RTAPI
/* A record offset the thread follows: inside the record heap, which only the HAL core
 * writes (users map it read-only in the kernel flavor). Checked anyway, every time. */
static bool record_ok(rtapi_u32 off, rtapi_u32 len)
{
	return off >= hal_seg->heap_start && off < hal_seg->val_start && len <= hal_seg->val_start - off;
}

static void run_functions(struct hal_thread_rec *t)
{
	long long start = rtapi_get_clocks(), prev = start, now;
	long long t0 = rtapi_get_time();
	rtapi_u32 off;

	/* Odd while running. Marked before reading the list (full barrier), so
	 * hal_threads_quiesce() after unlinking an entry either sees us running or
	 * we see the list without it. */
	__atomic_add_fetch(&t->cycle_seq, 1, __ATOMIC_SEQ_CST);
	off = __atomic_load_n(&t->first_entry_off, __ATOMIC_SEQ_CST);
	while (off) {
		struct hal_entry_rec *e;
		struct hal_funct_rec *f;
		hal_funct_t fn;

		if (!record_ok(off, sizeof(*e)))
			break;
		e = hal_ptr(off);
		if (!record_ok(e->funct_off, sizeof(*f)))
			break;
		f = hal_ptr(e->funct_off);
		fn = (hal_funct_t)(unsigned long)f->funct;

		fn((void *)(unsigned long)f->arg, (long)t->period_ns);
		now = rtapi_get_clocks();
		*f->time_ptr = (rtapi_s32)(now - prev);
		if (*f->time_ptr > f->tmax)
			f->tmax = *f->time_ptr;
		prev = now;
		off = __atomic_load_n(&e->next_off, __ATOMIC_ACQUIRE);
	}
	*t->time_ptr = (rtapi_s32)(prev - start);
	if (*t->time_ptr > t->tmax)
		t->tmax = *t->time_ptr;
	rtapi_store_u64(&t->run_ns, t->run_ns + (rtapi_u64)(rtapi_get_time() - t0));
	rtapi_store_u64(&t->cycles, t->cycles + 1);
	__atomic_add_fetch(&t->cycle_seq, 1, __ATOMIC_ACQ_REL);	/* even: idle */
}

/* Publish the periods the task missed (counted by RTAPI in rtapi_task_wait()) in the
 * record, for "show thread" and the host's warnings, and on the pin, for a watchdog. */
static void note_overruns(struct hal_thread_rec *t)
{
	long long n = rtapi_task_overruns(t->task_id);

	if (n <= 0 || (rtapi_u64)n == t->overruns)
		return;
	rtapi_store_u64(&t->overruns, (rtapi_u64)n);
	*t->overruns_ptr = n > 0x7fffffffLL ? 0x7fffffff : (hal_s32_t)n;
}

static void hal_thread_task(void *arg)
{
	struct hal_thread_rec *t = arg;

	for (;;) {
		int running = __atomic_load_n(&hal_seg->threads_running, __ATOMIC_ACQUIRE);

#ifndef __KERNEL__
		running = rtapi_task_lockstep_gate(running);	/* exact periods: "start" in step */
#endif
		if (running)
			run_functions(t);
		rtapi_task_wait();
		note_overruns(t);
	}
}

/* Base period and rounding (hal_create_thread(3hal)); returns the period or -errno. */
static long long thread_period(const char *name, unsigned long period)
{
	long long base = hal_seg->base_period_ns;
	rtapi_u64 n;

	if (period < 1000) {
		rtapi_print_msg(RTAPI_MSG_ERR, "thread '%s': period %lu ns is too short (minimum 1000)\n",
				name, period);
		return -EINVAL;
	}
	if (hal_seg->count[HAL_KIND_THREAD] == 0) {
		/* The clock may still run from an earlier session in this address space:
		 * keep it, as asking again only gets an error message from RTAPI. */
		long r = rtapi_clock_set_period(0);

		if (r == 0)
			r = rtapi_clock_set_period((long)period);
		if (r <= 0) {
			rtapi_print_msg(RTAPI_MSG_ERR, "thread '%s': cannot set clock period %lu ns\n",
					name, period);
			return -EINVAL;
		}
		/* setexact_for_test_suite_only: pretend the clock runs at the asked period,
		 * so test results do not depend on the clock's granularity. */
		if (hal_seg->exact_periods)
			r = (long)period;
		hal_seg->base_period_ns = r;
		base = r;
	}
	if ((long long)period < base) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"thread '%s': period %lu ns is shorter than the base period %lld ns "
				"(create the fastest thread first)\n", name, period, base);
		return -EINVAL;
	}
	n = rtapi_div_u64((rtapi_u64)period + (rtapi_u64)base / 2, (rtapi_u32)base);
	return (long long)n * base;
}

static int overruns_pin_new(const char *name, struct hal_thread_rec *t)
{
	char buf[HAL_NAME_LEN + 12];

	rtapi_snprintf(buf, sizeof(buf), "%s.overruns", name);
	return hal_pin_new_locked(buf, HAL_S32, HAL_OUT, (void **)&t->overruns_ptr, 0);
}
#endif

/* caller holds the HAL lock (hal_request.c: halcmd setexact_for_test_suite_only) */
int hal_set_exact_periods_locked(void)
{
	if (hal_seg->count[HAL_KIND_THREAD]) {
		rtapi_print_msg(RTAPI_MSG_ERR, "setexact_for_test_suite_only: a thread exists already: "
				"it must come before the first thread is created\n");
		return -EBUSY;
	}
	hal_seg->exact_periods = 1;
	rtapi_print_msg(RTAPI_MSG_INFO, "HAL takes thread periods exactly as asked; "
			"this mode is not suitable for running real hardware\n");
	return 0;
}

static void overruns_pin_delete(const char *name)
{
	char buf[HAL_NAME_LEN + 12];
	struct hal_pin_rec *pin;

	rtapi_snprintf(buf, sizeof(buf), "%s.overruns", name);
	pin = hal_find(HAL_KIND_PIN, buf);
	if (pin)
		hal_pin_delete_locked(pin);
}

#ifdef RTAPI
static int create_locked(const char *name, unsigned long period, int uses_fp)
{
	struct hal_thread_rec *t;
	long long actual;
	int prio, i, err;

	err = hal_check_lock(HAL_LOCK_LOAD, "create threads");
	if (err)
		return err;
	actual = thread_period(name, period);
	if (actual < 0)
		return (int)actual;
	/* Rate-monotonic: each later (slower) thread one step lower. */
	prio = rtapi_prio_highest();
	for (i = 0; i < (int)hal_seg->count[HAL_KIND_THREAD]; i++)
		prio = rtapi_prio_next_lower(prio);
	t = hal_object_new(HAL_KIND_THREAD, sizeof(*t), name, 0, &err);
	if (!t)
		return err;
	t->period_ns = actual;
	t->priority = prio;
	t->uses_fp = uses_fp != 0;
	err = hal_timing_objects_new(name, &t->time_ptr, &t->tmax, 0);
	if (err)
		goto undo_record;
	err = overruns_pin_new(name, t);
	if (err)
		goto undo_timing;
#ifndef __KERNEL__
	rtapi_task_lockstep(hal_seg->exact_periods);	/* repeatable runs for test suites */
#endif
	t->task_id = rtapi_task_new(hal_thread_task, t, prio, 0, uses_fp);
	if (t->task_id < 0) {
		err = t->task_id;
		rtapi_print_msg(RTAPI_MSG_ERR, "thread '%s': cannot create its task (%d)\n", name, err);
		goto undo_timing;
	}
	err = rtapi_task_start(t->task_id, (unsigned long)actual);
	if (err < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "thread '%s': cannot start its task (%d)\n", name, err);
		goto undo_task;
	}
	return 0;

undo_task:
	rtapi_task_delete(t->task_id);
undo_timing:
	overruns_pin_delete(name);
	hal_timing_objects_delete(name);
undo_record:
	hal_object_delete(&t->hdr);
	return err;
}
#endif

int hal_create_thread(const char *name, unsigned long period, int uses_fp)
{
#ifdef ULAPI
	rtapi_print_msg(RTAPI_MSG_ERR, "thread '%s': only realtime components can create threads\n",
			name);
	return -EINVAL;
#else
	int rc;

	if (!hal_seg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "thread '%s': call hal_init first\n", name);
		return -EINVAL;
	}
	hal_lock();
	rc = create_locked(name, period, uses_fp);
	if (rc < 0 && hal_seg->count[HAL_KIND_THREAD] == 0)
		hal_seg->base_period_ns = 0;	/* a refused first thread sets no base period */
	hal_unlock();
	if (rc == 0)
		hal_local_users++;	/* the task needs the mapping until it is deleted */
	return rc;
#endif
}

void hal_thread_delete_locked(struct hal_thread_rec *t)
{
	rtapi_u32 off;

#ifdef RTAPI
	rtapi_task_delete(t->task_id);	/* returns once the task has stopped */
#endif
	for (off = t->first_entry_off; off;) {
		struct hal_entry_rec *e = hal_ptr(off);

		off = e->next_off;
		((struct hal_funct_rec *)hal_ptr(e->funct_off))->users--;
		hal_os_code_put(((struct hal_funct_rec *)hal_ptr(e->funct_off))->module);	/* task stopped */
		hal_free_block(hal_seg, e);
	}
	t->first_entry_off = 0;
	overruns_pin_delete(t->hdr.name);
	hal_timing_objects_delete(t->hdr.name);
	hal_object_delete(&t->hdr);
	hal_heap_compact(hal_seg);	/* its blocks were freed one by one: merge them */
	if (hal_seg->count[HAL_KIND_THREAD] == 0)
		hal_seg->base_period_ns = 0;
}

int hal_thread_delete(const char *name)
{
	struct hal_thread_rec *t;
	int rc = 0;

	if (!hal_seg)
		return -EINVAL;
	hal_lock();
	t = hal_find(HAL_KIND_THREAD, name);
#ifdef ULAPI
	if (t) {
		rtapi_print_msg(RTAPI_MSG_ERR, "thread '%s' belongs to the realtime host\n", name);
		rc = -EPERM;
	}
#else
	if (t)
		hal_thread_delete_locked(t);
#endif
	hal_unlock();
	if (!t) {
		rtapi_print_msg(RTAPI_MSG_ERR, "thread '%s' does not exist\n", name);
		rc = -ENOENT;
	}
#ifdef RTAPI
	if (t)
		hal_local_user_gone();
#endif
	return rc;
}

int hal_thread_count(void)
{
	return hal_seg ? (int)hal_seg->count[HAL_KIND_THREAD] : 0;
}

#ifdef RTAPI
int hal_thread_overruns(void (*cb)(const char *name, long long period_ns,
				   unsigned long long overruns, void *ctx), void *ctx)
{
	struct hal_obj_hdr *o;
	int n = 0;

	if (!hal_seg)
		return -EINVAL;
	hal_lock();
	for (o = hal_first(HAL_KIND_THREAD); o; o = hal_next(o), n++) {
		struct hal_thread_rec *t = (struct hal_thread_rec *)o;

		cb(t->hdr.name, t->period_ns, rtapi_load_u64(&t->overruns), ctx);
	}
	hal_unlock();
	return n;
}

int hal_exit_threads(void)
{
	struct hal_obj_hdr *o;
	int n = 0, i;

	if (!hal_seg)
		return 0;
	hal_lock();
	while ((o = hal_first(HAL_KIND_THREAD)) != 0) {
		hal_thread_delete_locked((struct hal_thread_rec *)o);
		n++;
	}
	hal_unlock();
	for (i = 0; i < n; i++)
		hal_local_user_gone();
	return n;
}
#endif

int hal_set_running_locked(int running)
{
	int rc = hal_check_lock(HAL_LOCK_RUN, running ? "start threads" : "stop threads");

	if (!rc) {
		__atomic_store_n(&hal_seg->threads_running, running, __ATOMIC_RELEASE);
		if (!running)
			hal_threads_quiesce();
	}
	return rc;
}

static int set_running(int running)
{
	int rc;

	if (!hal_seg)
		return -EINVAL;
#ifdef ULAPI
	return hal_ul_names(running ? HAL_REQ_START : HAL_REQ_STOP, 0, 0, 0);
#endif
	hal_lock();
	rc = hal_set_running_locked(running);
	hal_unlock();
	return rc;
}

int hal_start_threads(void)
{
	return set_running(1);
}

int hal_stop_threads(void)
{
	return set_running(0);
}

/* Wait until every thread that was running its functions has finished that cycle:
 * then no thread is inside a function whose entry was unlinked before the call, and
 * the module references of those entries are dropped (puts_pending). Never gives up,
 * so a module is never freed under a thread; a thread stuck inside a function is
 * named once a second. */
void hal_threads_quiesce(void)
{
	struct hal_obj_hdr *o;

	__atomic_thread_fence(__ATOMIC_SEQ_CST);	/* pairs with run_functions() */
	for (o = hal_first(HAL_KIND_THREAD); o; o = hal_next(o)) {
		struct hal_thread_rec *t = (struct hal_thread_rec *)o;
		rtapi_u32 seq = __atomic_load_n(&t->cycle_seq, __ATOMIC_ACQUIRE);
		int waited;

		for (waited = 1; seq & 1; waited++) {
			rtapi_sleep_ns(100000);
			if (__atomic_load_n(&t->cycle_seq, __ATOMIC_ACQUIRE) != seq)
				break;
			if (waited % 10000 == 0)
				rtapi_print_msg(RTAPI_MSG_ERR,
						"HAL: waited %d s for thread '%s' to leave its functions\n",
						waited / 10000, t->hdr.name);
		}
	}
	for (o = hal_first(HAL_KIND_FUNCT); o; o = hal_next(o)) {
		struct hal_funct_rec *f = (struct hal_funct_rec *)o;

		for (; f->puts_pending; f->puts_pending--)
			hal_os_code_put(f->module);
	}
}
