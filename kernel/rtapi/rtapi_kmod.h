/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_kmod.h - what the files of rtapi.ko share with each other (kernel flavor only).
 * Not for components: they use rtapi.h. */
#ifndef RTAPI_KMOD_H
#define RTAPI_KMOD_H

#include <linux/mutex.h>
#include "rtapi.h"

#define RTAPI_MAX_MODULES	64
#define RTAPI_MAX_TASKS		64
#define RTAPI_MAX_SHMEMS	32

/* Serialises registration (modules, tasks, segments): init/cleanup/user context only,
 * never taken by a realtime task. */
extern struct mutex rtapi_kmod_lock;

/* rtapi_time_kmod.c: frees the clock period when the last task is gone; lock held */
void rtapi_clock_reset(void);

/* rtapi_module_kmod.c */
const char *rtapi_module_name(int module_id);	/* NULL when not registered; lock held */
int rtapi_module_valid(int module_id);		/* lock held */

/* Setup and teardown of each part, called from rtapi.ko's init/exit in order. */
int rtapi_shmem_kmod_init(void);
void rtapi_shmem_kmod_exit(void);
int rtapi_proc_kmod_init(void);
void rtapi_proc_kmod_exit(void);
void rtapi_task_kmod_exit(void);	/* stops tasks left behind (a bug in some module) */

/* rtapi_print_kmod.c: formats, keeps in the message ring and prints one message
 * unless 'level' is above the message level (RTAPI_MSG_ALL: always). */
void rtapi_vprint_msg_kmod(int level, const char *fmt, va_list ap);

/* /proc/rtapi writers: each prints its table (rtapi_kmod_lock taken inside). */
struct seq_file;
void rtapi_module_show(struct seq_file *m);
void rtapi_task_show(struct seq_file *m);
void rtapi_shmem_show(struct seq_file *m);
void rtapi_message_show(struct seq_file *m);	/* "next SEQ", then "SEQ LEVEL TEXT" lines */

#endif /* RTAPI_KMOD_H */
