/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_proc_kmod.c - /proc/rtapi/{modules,tasks,shmem,messages}: what rtapi.ko holds, for
 * people and tests (kernel flavor). */
#include <linux/module.h>
#include <linux/proc_fs.h>
#include <linux/seq_file.h>
#include "rtapi_kmod.h"

static struct proc_dir_entry *dir;

static int modules_show(struct seq_file *m, void *v) { rtapi_module_show(m); return 0; }
static int tasks_show(struct seq_file *m, void *v) { rtapi_task_show(m); return 0; }
static int shmem_show(struct seq_file *m, void *v) { rtapi_shmem_show(m); return 0; }
static int messages_show(struct seq_file *m, void *v) { rtapi_message_show(m); return 0; }

int rtapi_proc_kmod_init(void)
{
	dir = proc_mkdir("rtapi", NULL);
	if (!dir)
		goto fail;
	if (!proc_create_single("modules", 0444, dir, modules_show) ||
	    !proc_create_single("tasks", 0444, dir, tasks_show) ||
	    !proc_create_single("shmem", 0444, dir, shmem_show) ||
	    !proc_create_single("messages", 0444, dir, messages_show))
		goto fail;
	return 0;
fail:
	proc_remove(dir);	/* removes whatever entries were made; NULL is fine */
	printk(KERN_ERR "RTAPI: cannot create /proc/rtapi\n");
	return -ENOMEM;
}

void rtapi_proc_kmod_exit(void)
{
	proc_remove(dir);
}
