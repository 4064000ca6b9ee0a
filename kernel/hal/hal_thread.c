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
/* rtapi_get_clocks() inline: on x86 it is the TSC in both flavors (get_cycles() in
 * the kernel), and the call to it cost a tenth of the time of a small function. */
static inline long long thread_clocks(void)
{
#if defined(__x86_64__) || defined(__i386__)
	return (long long)__builtin_ia32_rdtsc();
#else
	return rtapi_get_clocks();
#endif
}

/* One cycle: every function of the dispatch table, in order. One clock read between
 * two functions (the end of one is the start of the next); the table is contiguous;
 * nothing here is a locked instruction or writes a line that configuring processes
 * write (issue 20). The table and its count are only ever published by the HAL core
 * with release stores after they are complete (hal_dispatch_append/rebuild). */
static void run_functions(struct hal_thread_rec *t, struct hal_thread_rt *rt)
{
	const struct hal_dispatch *d = hal_ptr(__atomic_load_n(&t->dispatch_off, __ATOMIC_ACQUIRE));
	rtapi_u32 i, n = d ? __atomic_load_n(&d->count, __ATOMIC_ACQUIRE) : 0;
	long period = (long)t->period_ns;
	long long t0 = rtapi_get_time();
	long long start = thread_clocks(), prev = start, now;
	rtapi_s32 dt;

	for (i = 0; i < n; i++) {
		const struct hal_dispatch_slot *sl = &d->slot[i];
		struct hal_funct_rec *f = (struct hal_funct_rec *)(hal_shmem_base + sl->funct_off);

		((hal_funct_t)(unsigned long)sl->funct)((void *)(unsigned long)sl->arg, period);
		now = thread_clocks();
		dt = (rtapi_s32)(now - prev);
		*f->time_ptr = dt;
		if (dt > f->tmax)
			f->tmax = dt;
		prev = now;
	}
	dt = (rtapi_s32)(prev - start);
	*t->time_ptr = dt;
	if (dt > rt->tmax)
		rt->tmax = dt;
	rtapi_store_u64(&rt->run_ns, rt->run_ns + (rtapi_u64)(rtapi_get_time() - t0));
	rtapi_store_u64(&rt->cycles, rt->cycles + 1);
}

/* Publish the periods the task missed (counted by RTAPI in rtapi_task_wait()) in the
 * record, for "show thread" and the host's warnings, and on the pin, for a watchdog. */
static void note_overruns(struct hal_thread_rec *t, struct hal_thread_rt *rt)
{
	long long n = rtapi_task_overruns(t->task_id);

	if (n <= 0 || (rtapi_u64)n == rt->overruns)
		return;
	rtapi_store_u64(&rt->overruns, (rtapi_u64)n);
	*t->overruns_ptr = n > 0x7fffffffLL ? 0x7fffffff : (hal_s32_t)n;
}

/* Each period ends with a release store of 'periods': everything the thread read
 * during the period (the dispatch table above all) is behind it. wait_for_thread()
 * builds on that instead of the thread announcing cycles with locked instructions. */
static void hal_thread_task(void *arg)
{
	struct hal_thread_rec *t = arg;
	struct hal_thread_rt *rt = hal_ptr(t->rt_off);

	for (;;) {
		rtapi_u32 done = rt->periods + 1;
		int running = __atomic_load_n(&hal_seg->threads_running, __ATOMIC_ACQUIRE);

#ifndef __KERNEL__
		running = rtapi_task_lockstep_gate(running);	/* exact periods: "start" in step */
#endif
		if (running)
			run_functions(t, rt);
		else
			__atomic_store_n(&rt->idle_period, done, __ATOMIC_RELAXED);
		__atomic_store_n(&rt->periods, done, __ATOMIC_RELEASE);
		rtapi_task_wait();
		note_overruns(t, rt);
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

static void thread_rt_free(struct hal_thread_rec *t)
{
	struct hal_thread_rt *rt = hal_ptr(t->rt_off);

	if (rt)
		hal_free_block(hal_seg, hal_ptr(rt->block_off));
	t->rt_off = 0;
}

/* --- dispatch tables (struct hal_dispatch, hal_layout.h) --- */

static void slot_fill(struct hal_dispatch_slot *sl, rtapi_u32 funct_off)
{
	const struct hal_funct_rec *f = hal_ptr(funct_off);

	sl->funct = f->funct;
	sl->arg = f->arg;
	sl->funct_off = funct_off;
	sl->pad = 0;
}

/* A new table holding the entry list of 't', published; the old one waits in
 * retired_off for hal_threads_quiesce(), which the caller must call before the
 * thread's table changes again. 0 or -ENOMEM (nothing changed). */
int hal_dispatch_rebuild(struct hal_thread_rec *t)
{
	rtapi_u32 n = t->entry_count, cap = n + n / 2 + 8, i = 0, off;
	struct hal_dispatch *d;

	if (t->retired_off)
		hal_threads_quiesce();	/* one old table at a time */
	if (n == 0) {		/* no functions, no table */
		t->retired_off = t->dispatch_off;
		__atomic_store_n(&t->dispatch_off, 0, __ATOMIC_RELEASE);
		return 0;
	}
	d = hal_alloc_block(hal_seg, sizeof(*d) + cap * (rtapi_u32)sizeof(d->slot[0]),
			    HAL_KIND_DISPATCH, 0);
	if (!d)
		return -ENOMEM;
	d->capacity = cap;
	for (off = t->first_entry_off; off && i < cap; i++) {
		const struct hal_entry_rec *e = hal_ptr(off);

		slot_fill(&d->slot[i], e->funct_off);
		off = e->next_off;
	}
	d->count = i;
	t->retired_off = t->dispatch_off;
	__atomic_store_n(&t->dispatch_off, hal_off(d), __ATOMIC_RELEASE);
	return 0;
}

/* The function of the list's last entry, appended: in place when the table has room
 * (the slot is written before the count that makes the thread read it), else in a
 * new table with room to grow, so n appends cost O(n) in all. 0 or -ENOMEM. */
int hal_dispatch_append(struct hal_thread_rec *t)
{
	struct hal_dispatch *d = hal_ptr(t->dispatch_off);
	const struct hal_entry_rec *e = hal_ptr(t->last_entry_off);

	if (!d || d->count + 1 != t->entry_count || d->count == d->capacity)
		return hal_dispatch_rebuild(t);
	slot_fill(&d->slot[d->count], e->funct_off);
	__atomic_store_n(&d->count, d->count + 1, __ATOMIC_RELEASE);
	return 0;
}

/* Has thread 't' passed a period boundary since everything published before this
 * call? With threads stopped, a thread whose last period ran nothing has: it will
 * read threads_running as 0 again (we hold the HAL mutex, nobody starts them), so it
 * will not look at its table. Otherwise wait for two boundaries: the period that may
 * have read the old table, and one begun after the new one was visible (a period
 * starts after the thread's sleep, a full barrier in both flavors, but two cost only
 * a period more). Never gives up, so nothing is freed under a thread; a thread stuck
 * inside a function is named once a second. */
static void wait_for_thread(struct hal_thread_rec *t, bool stopped)
{
	struct hal_thread_rt *rt = hal_ptr(t->rt_off);
	rtapi_u32 p0, p;
	int waited;

	if (!rt)
		return;
	p0 = __atomic_load_n(&rt->periods, __ATOMIC_ACQUIRE);
	for (waited = 1;; waited++) {
		if (rt->host_pid && !hal_os_pid_alive(rt->host_pid))
			return;	/* its host died: the thread runs no more (halrun -U cleans up) */
		p = __atomic_load_n(&rt->periods, __ATOMIC_ACQUIRE);
		if (stopped && __atomic_load_n(&rt->idle_period, __ATOMIC_RELAXED) == p)
			return;
		if (p - p0 >= 2)
			return;
		rtapi_sleep_ns(100000);
		if (waited % 10000 == 0)
			rtapi_print_msg(RTAPI_MSG_ERR,
					"HAL: waited %d s for thread '%s' to finish a period\n",
					waited / 10000, t->hdr.name);
	}
}

void hal_dispatch_shrink(struct hal_thread_rec *t)
{
	struct hal_dispatch *d;
	rtapi_u32 off, i = 0;

	if (hal_dispatch_rebuild(t) == 0)
		return;
	d = hal_ptr(t->dispatch_off);	/* no retired table: rebuild quiesced first */
	if (!d)
		return;
	rtapi_print_msg(RTAPI_MSG_WARN, "HAL shared memory is full: thread '%s' runs nothing "
			"for a period while its functions are rearranged\n", t->hdr.name);
	__atomic_store_n(&d->count, 0, __ATOMIC_RELEASE);
	__atomic_thread_fence(__ATOMIC_SEQ_CST);
	wait_for_thread(t, !__atomic_load_n(&hal_seg->threads_running, __ATOMIC_RELAXED));
	for (off = t->first_entry_off; off && i < d->capacity; i++) {
		const struct hal_entry_rec *e = hal_ptr(off);

		slot_fill(&d->slot[i], e->funct_off);
		off = e->next_off;
	}
	__atomic_store_n(&d->count, i, __ATOMIC_RELEASE);
}

/* After the HAL mutex was taken over from a dead process (hal_lock.c), which may have
 * died between changing a thread's entry list and its dispatch table: count every
 * list again and rebuild every table from it, then free what was retired. */
void hal_dispatch_repair(void)
{
	struct hal_obj_hdr *o;

	for (o = hal_first(HAL_KIND_THREAD); o; o = hal_next(o)) {
		struct hal_thread_rec *t = (struct hal_thread_rec *)o;
		rtapi_u32 off, n = 0, last = 0;

		for (off = t->first_entry_off; off; off = ((struct hal_entry_rec *)hal_ptr(off))->next_off) {
			n++;
			last = off;
		}
		t->entry_count = n;
		t->last_entry_off = last;
		hal_dispatch_shrink(t);	/* a rebuild, or in place when the heap is full */
	}
	hal_threads_quiesce();
}

#ifdef RTAPI
/* The thread's per-period state, at the first cache line boundary of its block, so
 * that nothing else shares its line. Its offset, not the block's, goes in rt_off. */
static struct hal_thread_rt *thread_rt_new(struct hal_thread_rec *t)
{
	char *block = hal_alloc_block(hal_seg, sizeof(struct hal_thread_rt) + HAL_CACHE_LINE,
				      HAL_KIND_THREAD_RT, 0);
	struct hal_thread_rt *rt;
	rtapi_u32 off;

	if (!block)
		return 0;
	off = (hal_off(block) + HAL_CACHE_LINE - 1) & ~(HAL_CACHE_LINE - 1);
	rt = hal_ptr(off);
	rt->idle_period = ~0u;	/* no period has passed: not known to be idle */
	rt->block_off = hal_off(block);
#ifndef __KERNEL__
	{
		char name[16];

		rt->host_pid = hal_os_self(name, sizeof(name));	/* this is rtapi_app */
	}
#endif
	t->rt_off = off;
	return rt;
}

static int create_locked(const char *name, unsigned long period, int uses_fp)
{
	struct hal_thread_rt *rt;
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
	rt = thread_rt_new(t);
	if (!rt) {
		rtapi_print_msg(RTAPI_MSG_ERR, "HAL shared memory is full: cannot create thread '%s'\n", name);
		err = -ENOMEM;
		goto undo_record;
	}
	err = hal_timing_objects_new(name, &t->time_ptr, &rt->tmax, 0);
	if (err)
		goto undo_rt;
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
undo_rt:
	thread_rt_free(t);
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
	if (t->dispatch_off)
		hal_free_block(hal_seg, hal_ptr(t->dispatch_off));
	if (t->retired_off)
		hal_free_block(hal_seg, hal_ptr(t->retired_off));
	t->dispatch_off = t->retired_off = 0;
	thread_rt_free(t);
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

		cb(t->hdr.name, t->period_ns,
		   rtapi_load_u64(&((struct hal_thread_rt *)hal_ptr(t->rt_off))->overruns), ctx);
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

/* Make what was unpublished safe to free: with threads running, wait until every
 * thread whose dispatch table was replaced has passed a period boundary (then free
 * the old table); with threads stopped (hal_set_running_locked(0) calls this right
 * after), until every thread has had a period that ran nothing. Then no thread is
 * inside a function whose entry was removed before the call, and the module
 * references of those entries are dropped (puts_pending). */
void hal_threads_quiesce(void)
{
	bool stopped = !__atomic_load_n(&hal_seg->threads_running, __ATOMIC_RELAXED);
	struct hal_obj_hdr *o;

	/* Our stores (tables, threads_running) before our loads of 'periods'. The
	 * configuring side's only full barrier; the threads need none. */
	__atomic_thread_fence(__ATOMIC_SEQ_CST);
	for (o = hal_first(HAL_KIND_THREAD); o; o = hal_next(o)) {
		struct hal_thread_rec *t = (struct hal_thread_rec *)o;

		if (stopped || t->retired_off)
			wait_for_thread(t, stopped);
		if (t->retired_off)
			hal_free_block(hal_seg, hal_ptr(t->retired_off));
		t->retired_off = 0;
	}
	for (o = hal_first(HAL_KIND_FUNCT); o; o = hal_next(o)) {
		struct hal_funct_rec *f = (struct hal_funct_rec *)o;

		for (; f->puts_pending; f->puts_pending--)
			hal_os_code_put(f->module);
	}
}
