/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_mutex_uspace.h - the holder record that rtapi_mutex_get() keeps in the mutex
 * word in the simulated-realtime flavor, so a process that dies holding a lock (a
 * halcmd killed in the middle of a .hal file) does not block every later one.
 * Exposed for the unit tests; not for components or tools. */
#ifndef RTAPI_MUTEX_USPACE_H
#define RTAPI_MUTEX_USPACE_H

#ifdef __cplusplus
extern "C" {
#endif

/* The word, while held by rtapi_mutex_get():
 *   bits 0..7    1: the byte rtapi_mutex_try() sets, so try() and the kernel flavor
 *                see the lock held whoever took it
 *   bits 8..31   the holder's pid (0: unknown, e.g. taken with rtapi_mutex_try())
 *   bits 32..63  the low 32 bits of the holder's start time (/proc/PID/stat field
 *                22), so a recycled pid is not mistaken for the holder
 * rtapi_mutex_give() stores 0 (the whole word). */
#define RTAPI_MUTEX_HELD 0xffUL

enum rtapi_mutex_holder {
	RTAPI_MUTEX_HOLDER_ALIVE,
	RTAPI_MUTEX_HOLDER_DEAD,	/* gone, a zombie, or its pid now names another process */
	RTAPI_MUTEX_HOLDER_UNKNOWN,	/* no record (pid 0): wait, never take over */
};

/* The word this process writes when it takes a lock (computed again after fork). */
unsigned long rtapi_mutex_self_word(void);
/* pid recorded in a held word (0 = no record). */
int rtapi_mutex_word_pid(unsigned long word);
/* Whether the process recorded in 'word' still exists, from /proc. */
enum rtapi_mutex_holder rtapi_mutex_holder_state(unsigned long word);

/* One attempt: take a free lock, or take over a lock whose holder is dead. Returns 0
 * when this process now holds it, else the word that holds it (nonzero). 'recovered'
 * is set to the dead holder's pid when the lock was taken over, else 0. */
unsigned long rtapi_mutex_try_recover(unsigned long *mutex, int *recovered);

/* How long rtapi_mutex_get() waits for a live holder before saying who it is waiting
 * for (once per holder), in ns. */
#define RTAPI_MUTEX_WARN_NS 5000000000LL

#ifdef __cplusplus
}
#endif
#endif /* RTAPI_MUTEX_USPACE_H */
