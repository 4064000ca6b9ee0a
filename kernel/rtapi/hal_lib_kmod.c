/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_lib_kmod.c - hal_lib.ko's init/exit and exports (kernel flavor). The HAL core
 * files are flavor independent; this file makes them one module: it keeps the HAL
 * segment mapped while hal_lib.ko is loaded, so userspace tools find it from the
 * first loadrt on, and exports the HAL API to components.
 *
 * It is also the kernel end of docs/kernel-security.md: the HAL segment is protected
 * (users map the record heap read-only, the value area writable), and userspace's
 * configuration requests, the HAL mutex and its recovery arrive here as /dev/rtapi
 * ioctls (hal_request.h), checked and executed by hal_req_execute(). */
#include <linux/module.h>
#include <linux/sched.h>
#include <linux/sched/signal.h>
#include <linux/pid.h>
#include <linux/slab.h>
#include <linux/uaccess.h>
#include <linux/delay.h>
#include "hal_internal.h"
#include "hal_host.h"
#include "rtapi_shmem_kmod.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("HAL: the hardware abstraction layer's realtime library");

/* --- the operating system for the HAL core (hal_internal.h) --- */

/* HAL_SIZE for the kernel flavor: halcmd passes the environment's value when it loads
 * hal_lib.ko (user/kmod); read once, at init, when the segment is made. */
static char *hal_size = "";
module_param(hal_size, charp, 0444);
MODULE_PARM_DESC(hal_size, "HAL segment size: bytes, or with a K, M or G suffix, 64M to 1G (default 64M)");

const char *hal_os_segment_size_text(void)
{
	return hal_size ? hal_size : "";
}

int hal_os_self(char *name, int len)
{
	strscpy(name, current->comm, len);
	return task_tgid_nr(current);
}

bool hal_os_pid_alive(int pid)
{
	struct task_struct *t;
	bool alive;

	rcu_read_lock();
	t = pid_task(find_vpid(pid), PIDTYPE_TGID);
	alive = t && !(t->flags & PF_EXITING);
	rcu_read_unlock();
	return alive;
}

/* A function's module stays loaded while the function is on a thread: rmmod of it
 * fails with EBUSY until "unloadrt" (HAL_REQ_MODULE_RELEASE) took it off. */
int hal_os_code_get(rtapi_u64 module)
{
	struct module *m = (struct module *)(unsigned long)module;

	if (m && !try_module_get(m))
		return -EBUSY;	/* being unloaded */
	return 0;
}

void hal_os_code_put(rtapi_u64 module)
{
	struct module *m = (struct module *)(unsigned long)module;

	if (m)
		module_put(m);
}

/* --- messages of a user's request go back to the user (hal_req.msg) --- */

static struct task_struct *capture_task;	/* the task running a request, or NULL */
static struct hal_req *capture_req;
static size_t capture_len;
static rtapi_msg_handler_t prev_handler;

static void msg_handler(msg_level_t level, const char *msg)
{
	if (READ_ONCE(capture_task) == current && capture_req) {
		size_t room = sizeof(capture_req->msg) - capture_len;
		ssize_t n = room > 1 ? strscpy(capture_req->msg + capture_len, msg, room) : 0;

		capture_len += n < 0 ? room - 1 : (size_t)n;	/* truncated: the buffer is full */
		return;
	}
	if (prev_handler) {
		prev_handler(level, msg);
		return;
	}
	if (level == RTAPI_MSG_ERR)
		printk(KERN_ERR "%s", msg);
	else if (level == RTAPI_MSG_WARN)
		printk(KERN_WARNING "%s", msg);
	else
		printk(KERN_INFO "%s", msg);
}

/* --- the HAL mutex for users: held by an open file of /dev/rtapi --- */

#define STATE_HOLDS_LOCK 1ul

/* Like hal_lock(), but a signal ends the wait (-EINTR), so a user waiting for a stuck
 * holder can be stopped; a live holder is named every 5 s, a dead one recovered. */
static int lock_for_user(void)
{
	char self_name[16], old_name[16];
	int self = hal_os_self(self_name, sizeof(self_name));
	unsigned long start = jiffies, next = jiffies + 5 * HZ;
	int dead;

	for (;;) {
		strscpy(old_name, hal_seg->mutex_holder, sizeof(old_name));
		if (hal_lock_try(hal_seg, self, self_name, &dead) == 0)
			break;
		if (signal_pending(current))
			return -EINTR;
		if (time_after(jiffies, next)) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"HAL: %s (pid %d) waiting %lu s for the HAL mutex held by pid %d (%s)\n",
					self_name, self, (jiffies - start) / HZ,
					(int)READ_ONCE(hal_seg->mutex_pid), hal_seg->mutex_holder);
			next = jiffies + 5 * HZ;
		}
		usleep_range(100, 500);
	}
	if (dead)
		rtapi_print_msg(RTAPI_MSG_ERR,
				"HAL: the HAL mutex was held by pid %d (%s), which is gone: recovered\n",
				dead, old_name);
	return 0;
}

static long do_request(unsigned long *state, struct hal_req __user *ureq)
{
	struct hal_caller caller = { .is_user = true };
	char name[16];
	struct hal_req *r;
	bool locked = false;
	long rc = 0;

	r = kmalloc(sizeof(*r), GFP_KERNEL);
	if (!r)
		return -ENOMEM;
	if (copy_from_user(r, ureq, sizeof(*r))) {
		rc = -EFAULT;
		goto out;
	}
	caller.pid = hal_os_self(name, sizeof(name));
	if (!(*state & STATE_HOLDS_LOCK)) {
		rc = lock_for_user();
		if (rc)
			goto out;
		locked = true;
	}
	capture_len = 0;
	capture_req = r;
	WRITE_ONCE(capture_task, current);
	r->result = hal_req_execute(r, &caller);
	WRITE_ONCE(capture_task, NULL);
	capture_req = NULL;
	r->msg[sizeof(r->msg) - 1] = 0;
	if (locked)
		hal_unlock();
	if (copy_to_user(ureq, r, sizeof(*r)))
		rc = -EFAULT;
out:
	kfree(r);
	return rc;
}

static long hook_ioctl(unsigned long *state, unsigned int cmd, unsigned long arg)
{
	struct hal_dev_info info;
	int rc;

	switch (cmd) {
	case HAL_IOC_INFO:
		memset(&info, 0, sizeof(info));
		info.size = hal_seg->size;
		info.val_start = hal_seg->val_start;
		info.layout_version = HAL_LAYOUT_VERSION;
		return copy_to_user((void __user *)arg, &info, sizeof(info)) ? -EFAULT : 0;
	case HAL_IOC_REQUEST:
		return do_request(state, (struct hal_req __user *)arg);
	case HAL_IOC_LOCK:
		if (*state & STATE_HOLDS_LOCK)
			return -EDEADLK;
		rc = lock_for_user();
		if (rc == 0)
			*state |= STATE_HOLDS_LOCK;
		return rc;
	case HAL_IOC_UNLOCK:
		if (!(*state & STATE_HOLDS_LOCK))
			return -EPERM;
		*state &= ~STATE_HOLDS_LOCK;
		hal_unlock();
		return 0;
	case HAL_IOC_RECOVER: {
		/* halcmd -R: free the mutex only from a holder that is gone. */
		unsigned long word = READ_ONCE(hal_seg->mutex);
		int pid = (int)(word >> 8), dead;	/* the holder's pid is in the word (hal_lock.c) */
		char name[16];

		if (!word)
			return 0;
		if (pid > 0 && hal_os_pid_alive(pid)) {
			rtapi_print_msg(RTAPI_MSG_ERR, "HAL: the HAL mutex is held by pid %d (%s), which "
					"is running: not released\n", pid, hal_seg->mutex_holder);
			return -EBUSY;
		}
		if (hal_lock_try(hal_seg, hal_os_self(name, sizeof(name)), name, &dead) == 0)
			hal_unlock();
		return 0;
	}
	default:
		return -ENOTTY;
	}
}

/* A process closed /dev/rtapi (or died) holding the HAL mutex: give it back. */
static void hook_release(unsigned long *state)
{
	if (!(*state & STATE_HOLDS_LOCK))
		return;
	*state &= ~STATE_HOLDS_LOCK;
	rtapi_print_msg(RTAPI_MSG_ERR, "HAL: pid %d (%s) went away holding the HAL mutex: released\n",
			(int)READ_ONCE(hal_seg->mutex_pid), hal_seg->mutex_holder);
	hal_unlock();
}

static const struct rtapi_dev_hook hal_dev_hook = {
	.owner = THIS_MODULE,
	.ioctl = hook_ioctl,
	.release = hook_release,
};

static int __init hal_lib_kmod_init(void)
{
	rtapi_u32 size;
	int rc;

	rc = hal_segment_size_wanted(&size);
	if (rc)
		return rc;
	/* Before the segment exists: users may never map its records writable. */
	rc = rtapi_shmem_kmod_protect_key(HAL_KEY, HAL_VAL_START(size));
	if (rc)
		return rc;
	rc = hal_segment_map();
	if (rc)
		return rc;
	hal_local_user_new();	/* our own hold: components come and go */
	prev_handler = rtapi_get_msg_handler();
	rtapi_set_msg_handler(msg_handler);
	rtapi_kmod_set_dev_hook(&hal_dev_hook);
	return 0;
}

static void __exit hal_lib_kmod_exit(void)
{
	rtapi_kmod_set_dev_hook(NULL);
	rtapi_set_msg_handler(prev_handler);
	hal_exit_threads();	/* threads outlive their modules, not hal_lib.ko */
	hal_local_users = 0;
	hal_segment_unmap();
}

module_init(hal_lib_kmod_init);
module_exit(hal_lib_kmod_exit);

EXPORT_SYMBOL(hal_init);
EXPORT_SYMBOL(hal_exit);
EXPORT_SYMBOL(hal_ready);
EXPORT_SYMBOL(hal_unready);
EXPORT_SYMBOL(hal_malloc);
EXPORT_SYMBOL(hal_set_constructor);
EXPORT_SYMBOL(hal_set_load_context);
EXPORT_SYMBOL(hal_set_load_module);
EXPORT_SYMBOL(hal_exit_module_comps);
EXPORT_SYMBOL(hal_exit_threads);
EXPORT_SYMBOL(hal_pin_new);
EXPORT_SYMBOL(hal_pin_bit_new);
EXPORT_SYMBOL(hal_pin_bit_newf);
EXPORT_SYMBOL(hal_pin_float_new);
EXPORT_SYMBOL(hal_pin_float_newf);
EXPORT_SYMBOL(hal_pin_s32_new);
EXPORT_SYMBOL(hal_pin_s32_newf);
EXPORT_SYMBOL(hal_pin_u32_new);
EXPORT_SYMBOL(hal_pin_u32_newf);
EXPORT_SYMBOL(hal_param_new);
EXPORT_SYMBOL(hal_param_bit_new);
EXPORT_SYMBOL(hal_param_bit_newf);
EXPORT_SYMBOL(hal_param_float_new);
EXPORT_SYMBOL(hal_param_float_newf);
EXPORT_SYMBOL(hal_param_s32_new);
EXPORT_SYMBOL(hal_param_s32_newf);
EXPORT_SYMBOL(hal_param_u32_new);
EXPORT_SYMBOL(hal_param_u32_newf);
EXPORT_SYMBOL(hal_param_set);
EXPORT_SYMBOL(hal_pin_alias);
EXPORT_SYMBOL(hal_pin_s64_new);
EXPORT_SYMBOL(hal_pin_s64_newf);
EXPORT_SYMBOL(hal_pin_u64_new);
EXPORT_SYMBOL(hal_pin_u64_newf);
EXPORT_SYMBOL(hal_param_s64_new);
EXPORT_SYMBOL(hal_param_s64_newf);
EXPORT_SYMBOL(hal_param_u64_new);
EXPORT_SYMBOL(hal_param_u64_newf);
EXPORT_SYMBOL(hal_param_alias);
EXPORT_SYMBOL(hal_param_bit_set);
EXPORT_SYMBOL(hal_param_float_set);
EXPORT_SYMBOL(hal_param_s32_set);
EXPORT_SYMBOL(hal_param_u32_set);
EXPORT_SYMBOL(hal_signal_new);
EXPORT_SYMBOL(hal_signal_delete);
EXPORT_SYMBOL(hal_link);
EXPORT_SYMBOL(hal_unlink);
EXPORT_SYMBOL(hal_export_funct);
EXPORT_SYMBOL(hal_create_thread);
EXPORT_SYMBOL(hal_thread_delete);
EXPORT_SYMBOL(hal_add_funct_to_thread);
EXPORT_SYMBOL(hal_del_funct_from_thread);
EXPORT_SYMBOL(hal_start_threads);
EXPORT_SYMBOL(hal_stop_threads);
EXPORT_SYMBOL(hal_set_lock);
EXPORT_SYMBOL(hal_get_lock);
