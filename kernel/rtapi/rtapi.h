/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi.h - the RTAPI interface (rtapi(3rtapi) and its pages), the only header
 * realtime code needs besides hal.h. The same declarations serve both flavors;
 * the few type/errno differences between kernel and userspace live here and in
 * kernel/rtapi/, never in components. */
#ifndef RTAPI_H
#define RTAPI_H

#if defined(__KERNEL__)
#include <linux/types.h>
#include <linux/errno.h>
#include <linux/stddef.h>
#include <linux/stdarg.h>
#else
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <errno.h>
#include <stdarg.h>
#include <linux/types.h>	/* __u32, __s32, __u64 as the hal_type_t page names them */
#endif

#if !defined(RTAPI) && !defined(ULAPI)
#error "define RTAPI (realtime code) or ULAPI (userspace code) before including rtapi.h"
#endif

#ifdef __cplusplus
extern "C" {
#endif

typedef __u8 rtapi_u8;
typedef __s8 rtapi_s8;
typedef __u16 rtapi_u16;
typedef __s16 rtapi_s16;
typedef __u32 rtapi_u32;
typedef __s32 rtapi_s32;
typedef __u64 rtapi_u64;
typedef __s64 rtapi_s64;

#define RTAPI_NAME_LEN 31	/* module names are truncated to this */

/* Message levels (rtapi_print_msg(3rtapi)). */
typedef enum {
	RTAPI_MSG_NONE = 0,
	RTAPI_MSG_ERR,
	RTAPI_MSG_WARN,
	RTAPI_MSG_INFO,
	RTAPI_MSG_DBG,
	RTAPI_MSG_ALL
} msg_level_t;

/* --- module registration: init/cleanup code only --- */
int rtapi_init(const char *modname);	/* > 0 module id, or -errno */
int rtapi_exit(int module_id);

/* --- formatting and messages: any context --- */
int rtapi_snprintf(char *buf, unsigned long int size, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
int rtapi_vsnprintf(char *buf, unsigned long int size, const char *fmt, va_list ap);
void rtapi_print(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void rtapi_print_msg(int level, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
int rtapi_set_msg_level(int level);	/* 0, or -EINVAL for a level outside NONE..ALL */
int rtapi_get_msg_level(void);
/* The handler receives the formatted message (not yet newline-stripped). */
typedef void (*rtapi_msg_handler_t)(msg_level_t level, const char *msg);
void rtapi_set_msg_handler(rtapi_msg_handler_t handler);	/* NULL restores the default */
rtapi_msg_handler_t rtapi_get_msg_handler(void);

/* --- time --- */
long int rtapi_clock_set_period(long int nsec);	/* 0 queries; first nonzero call starts */
void rtapi_delay(long int nsec);			/* busy-wait, capped at rtapi_delay_max() */
long int rtapi_delay_max(void);
long long rtapi_get_time(void);			/* monotonic ns */
long long rtapi_get_clocks(void);			/* CPU clocks (TSC) */

/* --- 64-bit division without libgcc helpers (rtapi_div_u64(3rtapi)) --- */
static inline __u64 rtapi_div_u64_rem(__u64 dividend, __u32 divisor, __u32 *remainder)
{
	*remainder = (__u32)(dividend % divisor);
	return dividend / divisor;
}
static inline __u64 rtapi_div_u64(__u64 dividend, __u32 divisor)
{
	return dividend / divisor;
}
static inline __s64 rtapi_div_s64(__s64 dividend, __s32 divisor)
{
	return dividend / divisor;
}

/* --- tearing-free 64-bit access for values realtime code writes and tools read --- */
static inline __u64 rtapi_load_u64(const volatile __u64 *p)
{
	return __atomic_load_n(p, __ATOMIC_RELAXED);
}
static inline void rtapi_store_u64(volatile __u64 *p, __u64 v)
{
	__atomic_store_n(p, v, __ATOMIC_RELAXED);
}

/* --- priorities (rtapi_prio(3rtapi)): higher number = higher priority --- */
int rtapi_prio_highest(void);
int rtapi_prio_lowest(void);
int rtapi_prio_next_higher(int prio);
int rtapi_prio_next_lower(int prio);

/* --- tasks: create/delete/start from init/cleanup code only --- */
int rtapi_task_new(void (*taskcode)(void *), void *arg, int prio,
		   unsigned long stacksize, int uses_fp);
int rtapi_task_delete(int task_id);
int rtapi_task_start(int task_id, unsigned long int period_nsec);
void rtapi_task_wait(void);	/* from inside a periodic task only */
void rtapi_wait(void);		/* older name of rtapi_task_wait */
int rtapi_task_pause(int task_id);
int rtapi_task_resume(int task_id);
int rtapi_task_self(void);	/* id of the calling task, or -EINVAL outside one */
/* Overruns (missed periods) counted for a task since it started. */
long long rtapi_task_overruns(int task_id);

/* --- floating point outside realtime functions ---
 * Init/exit code that must compute or assign floats calls a function of an FP
 * translation unit (*_fp.c) between these two: kernel_fpu_begin/end in the kernel
 * flavor (preemption is off in between: no hal_* calls, no sleeping, no printing),
 * nothing in the simulated flavor. Realtime functions exported with uses_fp = 1
 * already run inside an FPU section opened by their thread: never call these there. */
#if defined(__KERNEL__)
void rtapi_fpu_begin(void);
void rtapi_fpu_end(void);
#else
static inline void rtapi_fpu_begin(void) {}
static inline void rtapi_fpu_end(void) {}
#endif

/* --- shared memory (rtapi_shmem(3rtapi)) --- */
int rtapi_shmem_new(int key, int module_id, unsigned long int size);
int rtapi_shmem_delete(int shmem_id, int module_id);
int rtapi_shmem_getptr(int shmem_id, void **ptr);

/* --- mutexes: an unsigned long word, usable between kernel and userspace --- */
static inline int rtapi_mutex_try(unsigned long *mutex)
{
	return __atomic_test_and_set(mutex, __ATOMIC_ACQUIRE) ? 1 : 0;
}
void rtapi_mutex_get(unsigned long *mutex);	/* blocks: never from a realtime task */
/* Clears the whole word: the simulated flavor's rtapi_mutex_get() records its holder
 * in the bytes above the one rtapi_mutex_try() sets. */
static inline void rtapi_mutex_give(unsigned long *mutex)
{
	__atomic_store_n(mutex, 0UL, __ATOMIC_RELEASE);
}

/* --- hardware I/O (rtapi_outb(3rtapi), rtapi_region(3rtapi)) --- */
void rtapi_outb(unsigned char byte, unsigned int port);
unsigned char rtapi_inb(unsigned int port);
void rtapi_outw(unsigned short word, unsigned int port);
unsigned short rtapi_inw(unsigned int port);
void rtapi_outl(unsigned int word, unsigned int port);
unsigned int rtapi_inl(unsigned int port);
void *rtapi_request_region(unsigned long base, unsigned long int size, const char *name);
void rtapi_release_region(unsigned long base, unsigned long int size);

/* Process id of the caller (userspace), 0 in the kernel. */
long rtapi_getpid(void);
#ifndef __KERNEL__
/* Does process 'pid' still exist? Userspace only: HAL uses it to find userspace
 * components whose process died without hal_exit() (crash, kill -9). */
bool rtapi_process_exists(long pid);
#endif

#if defined(RTAPI) && !defined(__KERNEL__)
/* --- the simulated flavor's extras, as LinuxCNC's uspace RTAPI has them (init and
 * non-realtime code of out-of-tree modules; rtapi_extras_uspace.c) --- */
#include <spawn.h>
int rtapi_spawn_as_root(pid_t *pid, const char *path, const posix_spawn_file_actions_t *file_actions,
			const posix_spawnattr_t *attrp, char *const argv[], char *const envp[]);
int rtapi_spawnp_as_root(pid_t *pid, const char *path, const posix_spawn_file_actions_t *file_actions,
			 const posix_spawnattr_t *attrp, char *const argv[], char *const envp[]);
int rtapi_open_as_root(const char *filename, int mode);	/* fd, or -errno */
int rtapi_is_realtime(void);		/* PREEMPT_RT kernel and SCHED_FIFO allowed */
int rtapi_is_kernelspace(void);		/* 0 here */
/* The calling task's next release time (ns, rtapi_get_time's clock), and a correction
 * (ns, at most a tenth of the period either way) added to the following period only:
 * what a driver that locks the thread to an external clock uses. */
long long rtapi_task_pll_get_reference(void);
int rtapi_task_pll_set_correction(long value);
/* Lock-step mode for periodic tasks started from now on (HAL's setexact_for_test_suite_only):
 * one task runs at a time, in the order of their releases in virtual time (ties: higher
 * priority first), so runs repeat exactly. A lock-step task passes the value of a gate
 * (HAL: threads running) through _gate() at the top of each cycle and acts on what it
 * returns: when the gate has opened since any task last looked, every task becomes due
 * at this instant and the caller waits for its turn among them. Other callers get the
 * value back unchanged. */
void rtapi_task_lockstep(int on);
int rtapi_task_lockstep_gate(int value);
#endif

/* --- non-realtime helper used by HAL to wait for threads to finish a cycle --- */
void rtapi_sleep_ns(long long nsec);	/* init/cleanup/user code only */

#ifdef __cplusplus
}
#endif
#endif /* RTAPI_H */
