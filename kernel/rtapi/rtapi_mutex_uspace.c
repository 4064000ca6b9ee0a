/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_mutex_uspace.c - the blocking rtapi_mutex_get (rtapi_mutex(3rtapi)) of the
 * simulated-realtime flavor; try and give are inline in rtapi.h. The word is shared
 * between processes (the HAL mutex lives in the HAL segment), so a process killed
 * while holding it must not block the others forever: the holder writes its pid and
 * start time into the word (rtapi_mutex_uspace.h), and a waiter that finds the holder
 * dead takes the lock over with one compare-and-swap, saying so. A live holder that
 * keeps the lock past RTAPI_MUTEX_WARN_NS is named once, with what to do. */
#include <errno.h>
#include <fcntl.h>
#include <sched.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "rtapi.h"
#include "rtapi_mutex_uspace.h"

_Static_assert(sizeof(unsigned long) == 8, "the holder record needs a 64-bit mutex word");

#define PID_MASK 0xffffffUL	/* pid_max is at most 2^22 */

/* /proc/PID/stat: state (field 3) and start time (field 22). 'comm' (field 2) may
 * hold spaces and parentheses, so fields are counted from the last ')'. Returns
 * -1 when the process does not exist. */
static int read_stat(int pid, char *state, unsigned long long *start)
{
	char path[40], buf[1024], *p;
	int fd, field;
	ssize_t n;

	snprintf(path, sizeof(path), "/proc/%d/stat", pid);
	fd = open(path, O_RDONLY | O_CLOEXEC);
	if (fd < 0)
		return -1;
	n = read(fd, buf, sizeof(buf) - 1);
	close(fd);
	if (n <= 0)
		return -1;
	buf[n] = '\0';
	p = strrchr(buf, ')');
	if (!p || p[1] != ' ')
		return -1;
	p += 2;
	*state = *p;
	for (field = 3; field < 22 && p; field++) {
		p = strchr(p, ' ');
		if (p)
			p++;
	}
	if (!p || sscanf(p, "%llu", start) != 1)
		return -1;
	return 0;
}

static unsigned long make_word(int pid, unsigned long long start)
{
	return ((unsigned long)(start & 0xffffffffULL) << 32) |
	       (((unsigned long)pid & PID_MASK) << 8) | 1UL;
}

unsigned long rtapi_mutex_self_word(void)
{
	static int cached_pid;
	static unsigned long cached_word;
	int pid = (int)rtapi_getpid();
	unsigned long long start = 0;
	char state;

	if (__atomic_load_n(&cached_pid, __ATOMIC_ACQUIRE) == pid)
		return __atomic_load_n(&cached_word, __ATOMIC_RELAXED);
	if (read_stat(pid, &state, &start) < 0)
		start = 0;	/* no /proc: the pid alone is still a record */
	__atomic_store_n(&cached_word, make_word(pid, start), __ATOMIC_RELAXED);
	__atomic_store_n(&cached_pid, pid, __ATOMIC_RELEASE);
	return make_word(pid, start);
}

int rtapi_mutex_word_pid(unsigned long word)
{
	return (int)((word >> 8) & PID_MASK);
}

enum rtapi_mutex_holder rtapi_mutex_holder_state(unsigned long word)
{
	int pid = rtapi_mutex_word_pid(word);
	unsigned long long start;
	char state;

	if (pid == 0)
		return RTAPI_MUTEX_HOLDER_UNKNOWN;
	if (read_stat(pid, &state, &start) < 0)
		return errno == ENOENT || errno == ESRCH ? RTAPI_MUTEX_HOLDER_DEAD
							 : RTAPI_MUTEX_HOLDER_UNKNOWN;
	if (state == 'Z' || state == 'X')	/* killed, not yet reaped */
		return RTAPI_MUTEX_HOLDER_DEAD;
	if ((word >> 32) != 0 && (start & 0xffffffffULL) != (word >> 32))
		return RTAPI_MUTEX_HOLDER_DEAD;	/* the pid was reused */
	return RTAPI_MUTEX_HOLDER_ALIVE;
}

unsigned long rtapi_mutex_try_recover(unsigned long *mutex, int *recovered)
{
	unsigned long me = rtapi_mutex_self_word();
	unsigned long w = __atomic_load_n(mutex, __ATOMIC_RELAXED);

	*recovered = 0;
	if ((w & RTAPI_MUTEX_HELD) == 0)
		return __atomic_compare_exchange_n(mutex, &w, me, false, __ATOMIC_ACQUIRE,
						   __ATOMIC_RELAXED) ? 0 : (w ? w : 1);
	if (rtapi_mutex_holder_state(w) != RTAPI_MUTEX_HOLDER_DEAD)
		return w;
	/* Only one waiter wins: the others see our word, a live holder. */
	if (!__atomic_compare_exchange_n(mutex, &w, me, false, __ATOMIC_ACQUIRE, __ATOMIC_RELAXED))
		return w ? w : 1;
	*recovered = rtapi_mutex_word_pid(w);
	return 0;
}

static void holder_name(int pid, char *name, size_t size)
{
	char path[40];
	ssize_t n;
	int fd;

	snprintf(path, sizeof(path), "/proc/%d/comm", pid);
	snprintf(name, size, "?");
	fd = open(path, O_RDONLY | O_CLOEXEC);
	if (fd < 0)
		return;
	n = read(fd, name, size - 1);
	close(fd);
	if (n <= 0)
		n = 0;
	name[n] = '\0';
	name[strcspn(name, "\n")] = '\0';
}

/* A warning, not an error: halcmd shows warnings at once, but keeps a command's errors
 * until it ends, which a blocked command never would. */
static void say_waiting(unsigned long word)
{
	int pid = rtapi_mutex_word_pid(word);
	char name[32];

	if (pid == 0) {
		rtapi_print_msg(RTAPI_MSG_WARN, "rtapi: still waiting for a lock after %lld s; its "
				"holder is not recorded (realtime code?); if nothing progresses, run "
				"'halrun -U'\n", RTAPI_MUTEX_WARN_NS / 1000000000LL);
		return;
	}
	holder_name(pid, name, sizeof(name));
	rtapi_print_msg(RTAPI_MSG_WARN, "rtapi: still waiting for the HAL lock after %lld s: it is "
			"held by process %d (%s); if that process is stuck, end it (kill %d) and "
			"this one continues\n", RTAPI_MUTEX_WARN_NS / 1000000000LL, pid, name, pid);
}

void rtapi_mutex_get(unsigned long *mutex)
{
	unsigned long seen = 0, w;
	long long since = 0, now;
	int spins = 0, recovered, warned = 0;
	struct timespec nap = { 0, 1000000 };

	for (;;) {
		w = rtapi_mutex_try_recover(mutex, &recovered);
		if (w == 0)
			break;
		/* Short sections are the rule: yield a while, then stop burning a CPU. */
		if (++spins < 200) {
			sched_yield();
			continue;
		}
		now = rtapi_get_time();
		if (w != seen) {
			seen = w;
			since = now;
			warned = 0;
		} else if (!warned && now - since >= RTAPI_MUTEX_WARN_NS) {
			say_waiting(w);
			warned = 1;
		}
		nanosleep(&nap, NULL);
	}
	if (recovered)
		rtapi_print_msg(RTAPI_MSG_WARN, "rtapi: process %d died holding the HAL lock; "
				"taken over (check the HAL with 'halcmd show' if it died mid-change)\n",
				recovered);
}
