/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_lock.c - the HAL mutex (configuration changes) and the lock levels of
 * hal_set_lock(3hal). Realtime threads never take the mutex.
 *
 * The mutex is a word in the segment, shared by every process and the kernel; its
 * holder (pid and name) is recorded beside it, so a holder that died is detected and
 * the mutex recovered with a message naming it, and a live holder that keeps it past
 * HAL_LOCK_REPORT_NS is named in a message rather than hanging everybody silently.
 * In the kernel flavor users cannot write the segment header: they take the mutex
 * through the /dev/rtapi ioctl, and closing the device (a dying process) gives it back
 * (hal_lib_kmod.c). */
#include "hal_internal.h"
#include "rtapi_string.h"

#define HAL_LOCK_REPORT_NS 5000000000LL	/* name a live holder after 5 s, then every 5 s */

static bool (*pid_alive)(int pid) = hal_os_pid_alive;

void hal_lock_set_liveness_check(bool (*alive)(int pid))
{
	pid_alive = alive ? alive : hal_os_pid_alive;
}

/* The mutex word: 0 free, else (holder's pid << 8) | 1, written in one atomic step,
 * so a holder killed at any instant is known by its pid (a word without one, 1, was
 * taken by something that did not say who: it is waited for, never taken over). The
 * pid and name beside it are for messages only. */
static unsigned long word_of(int pid)
{
	return ((unsigned long)(unsigned)pid << 8) | 1ul;
}

static void set_holder(struct hal_seg_hdr *seg, int self, const char *name)
{
	rtapi_snprintf(seg->mutex_holder, sizeof(seg->mutex_holder), "%s", name);
	__atomic_store_n(&seg->mutex_pid, self, __ATOMIC_RELEASE);
}

int hal_lock_try(struct hal_seg_hdr *seg, int self, const char *name, int *dead_pid)
{
	unsigned long seen = 0;
	int pid;

	*dead_pid = 0;
	if (__atomic_compare_exchange_n(&seg->mutex, &seen, word_of(self), false, __ATOMIC_ACQUIRE,
					__ATOMIC_RELAXED)) {
		set_holder(seg, self, name);
		return 0;
	}
	pid = (int)(seen >> 8);
	if (pid <= 0 || pid == self || pid_alive(pid))
		return -EBUSY;
	/* Dead holder: take the mutex over from it. Only one waiter wins the exchange. */
	if (!__atomic_compare_exchange_n(&seg->mutex, &seen, word_of(self), false, __ATOMIC_ACQUIRE,
					 __ATOMIC_RELAXED))
		return -EBUSY;
	*dead_pid = pid;
	set_holder(seg, self, name);
	return 0;
}

void hal_lock_give(struct hal_seg_hdr *seg)
{
	__atomic_store_n(&seg->mutex_pid, 0, __ATOMIC_RELAXED);
	__atomic_store_n(&seg->mutex, 0ul, __ATOMIC_RELEASE);
}

void hal_lock_seg(struct hal_seg_hdr *seg)
{
	char self_name[16], old_name[16];
	long long start = 0, next_report = 0, now;
	int self = hal_os_self(self_name, sizeof(self_name));
	int dead, tries = 0;

	for (;;) {
		rtapi_snprintf(old_name, sizeof(old_name), "%s", seg->mutex_holder);
		if (hal_lock_try(seg, self, self_name, &dead) == 0)
			break;
		/* Short holds are the rule: yield a few times before sleeping. */
		if (++tries < 50) {
			rtapi_sleep_ns(0);
			continue;
		}
		now = rtapi_get_time();
		if (!start) {
			start = now;
			next_report = now + HAL_LOCK_REPORT_NS;
		} else if (now >= next_report) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"HAL: waiting %lld s for the HAL mutex held by pid %d (%s)\n",
					(long long)rtapi_div_u64((rtapi_u64)(now - start), 1000000000u),
					(int)__atomic_load_n(&seg->mutex_pid, __ATOMIC_ACQUIRE),
					seg->mutex_holder);
			next_report = now + HAL_LOCK_REPORT_NS;
		}
		rtapi_sleep_ns(200000);
	}
	if (dead) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"HAL: the HAL mutex was held by pid %d (%s), which is gone: recovered\n",
				dead, old_name);
		if (seg == hal_seg && seg->init_state == 2)
			hal_dispatch_repair();	/* it may have died inside addf/delf */
	}
}

void hal_lock(void)
{
#ifdef ULAPI
	if (hal_seg_is_kmod) {	/* the header is read-only here: ask the kernel */
		hal_kmod_lock(true);
		return;
	}
#endif
	hal_lock_seg(hal_seg);
}

void hal_unlock(void)
{
#ifdef ULAPI
	if (hal_seg_is_kmod) {
		hal_kmod_lock(false);
		return;
	}
#endif
	hal_lock_give(hal_seg);
}

static const char *level_name(unsigned level)
{
	switch (level) {
	case HAL_LOCK_LOAD: return "load";
	case HAL_LOCK_CONFIG: return "config";
	case HAL_LOCK_PARAMS: return "params";
	case HAL_LOCK_RUN: return "run";
	default: return "all";
	}
}

int hal_check_lock(unsigned level, const char *what)
{
	if (!(hal_seg->lock_level & level))
		return 0;
	rtapi_print_msg(RTAPI_MSG_ERR, "HAL is locked (%s): cannot %s; use 'unlock %s' first\n",
			level_name(level), what, level_name(level));
	return -EPERM;
}

int hal_set_lock_locked(unsigned lock_type)
{
	hal_seg->lock_level = lock_type & HAL_LOCK_ALL;
	return 0;
}

int hal_set_lock(unsigned char lock_type)
{
	int rc;

	if (!hal_seg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_set_lock: HAL is not initialised\n");
		return -EINVAL;
	}
#ifdef ULAPI
	return hal_ul_names(HAL_REQ_SET_LOCK, 0, 0, lock_type);
#endif
	hal_lock();
	rc = hal_set_lock_locked(lock_type);
	hal_unlock();
	return rc;
}

int hal_get_lock(void)
{
	if (!hal_seg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_get_lock: HAL is not initialised\n");
		return -EINVAL;
	}
	return (int)hal_seg->lock_level;
}
