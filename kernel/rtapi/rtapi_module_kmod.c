/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_module_kmod.c - rtapi.ko's own init/exit, and module registration
 * (rtapi_init(3rtapi), rtapi_exit(3rtapi)) in the kernel flavor. */
#include <linux/module.h>
#include <linux/seq_file.h>
#include <linux/string.h>
#include "rtapi_kmod.h"
#define RTAPI_MATH_NO_MACROS
#include "rtapi_math.h"
#include "rtapi_string.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("RTAPI: realtime tasks, shared memory and messages for HAL");

DEFINE_MUTEX(rtapi_kmod_lock);

static char module_names[RTAPI_MAX_MODULES][RTAPI_NAME_LEN + 1];
static bool module_used[RTAPI_MAX_MODULES];	/* index 0 unused: ids are > 0 */

int rtapi_module_valid(int module_id)
{
	return module_id > 0 && module_id < RTAPI_MAX_MODULES && module_used[module_id];
}

const char *rtapi_module_name(int module_id)
{
	return rtapi_module_valid(module_id) ? module_names[module_id] : NULL;
}

int rtapi_init(const char *modname)
{
	int id;

	mutex_lock(&rtapi_kmod_lock);
	for (id = 1; id < RTAPI_MAX_MODULES && module_used[id]; id++)
		;
	if (id == RTAPI_MAX_MODULES) {
		mutex_unlock(&rtapi_kmod_lock);
		rtapi_print_msg(RTAPI_MSG_ERR, "RTAPI: module '%s': all %d module slots in use\n",
				modname ? modname : "?", RTAPI_MAX_MODULES - 1);
		return -ENOMEM;
	}
	module_used[id] = true;
	strscpy(module_names[id], modname ? modname : "unnamed", sizeof(module_names[id]));
	mutex_unlock(&rtapi_kmod_lock);
	return id;
}
EXPORT_SYMBOL(rtapi_init);

int rtapi_exit(int module_id)
{
	int rc = 0;

	mutex_lock(&rtapi_kmod_lock);
	if (rtapi_module_valid(module_id))
		module_used[module_id] = false;
	else
		rc = -EINVAL;
	mutex_unlock(&rtapi_kmod_lock);
	return rc;
}
EXPORT_SYMBOL(rtapi_exit);

long rtapi_getpid(void)
{
	return 0;
}
EXPORT_SYMBOL(rtapi_getpid);

void rtapi_module_show(struct seq_file *m)
{
	int id;

	mutex_lock(&rtapi_kmod_lock);
	seq_puts(m, "ID  NAME\n");
	for (id = 1; id < RTAPI_MAX_MODULES; id++)
		if (module_used[id])
			seq_printf(m, "%-3d %s\n", id, module_names[id]);
	mutex_unlock(&rtapi_kmod_lock);
}

/* The flavor-independent files (math, strings) carry no exports. */
EXPORT_SYMBOL(rtapi_strlcpy);
EXPORT_SYMBOL(rtapi_strtol);
EXPORT_SYMBOL(rtapi_strtoul);
EXPORT_SYMBOL(rtapi_sin);
EXPORT_SYMBOL(rtapi_cos);
EXPORT_SYMBOL(rtapi_tan);
EXPORT_SYMBOL(rtapi_asin);
EXPORT_SYMBOL(rtapi_acos);
EXPORT_SYMBOL(rtapi_atan);
EXPORT_SYMBOL(rtapi_atan2);
EXPORT_SYMBOL(rtapi_sinh);
EXPORT_SYMBOL(rtapi_cosh);
EXPORT_SYMBOL(rtapi_tanh);
EXPORT_SYMBOL(rtapi_exp);
EXPORT_SYMBOL(rtapi_log);
EXPORT_SYMBOL(rtapi_log10);
EXPORT_SYMBOL(rtapi_pow);
EXPORT_SYMBOL(rtapi_sqrt);
EXPORT_SYMBOL(rtapi_fabs);
EXPORT_SYMBOL(rtapi_floor);
EXPORT_SYMBOL(rtapi_ceil);
EXPORT_SYMBOL(rtapi_fmod);
EXPORT_SYMBOL(rtapi_hypot);
EXPORT_SYMBOL(rtapi_round);
EXPORT_SYMBOL(rtapi_trunc);
EXPORT_SYMBOL(rtapi_rint);
EXPORT_SYMBOL(rtapi_copysign);
EXPORT_SYMBOL(rtapi_fmin);
EXPORT_SYMBOL(rtapi_fmax);
EXPORT_SYMBOL(rtapi_isnan);
EXPORT_SYMBOL(rtapi_isinf);
EXPORT_SYMBOL(rtapi_isfinite);

static int __init rtapi_kmod_init(void)
{
	int rc = rtapi_shmem_kmod_init();

	if (rc)
		return rc;
	rc = rtapi_proc_kmod_init();
	if (rc) {
		rtapi_shmem_kmod_exit();
		return rc;
	}
	rtapi_print_msg(RTAPI_MSG_INFO, "RTAPI: loaded\n");
	return 0;
}

static void __exit rtapi_kmod_exit(void)
{
	rtapi_task_kmod_exit();
	rtapi_proc_kmod_exit();
	rtapi_shmem_kmod_exit();
	rtapi_print_msg(RTAPI_MSG_INFO, "RTAPI: unloaded\n");
}

module_init(rtapi_kmod_init);
module_exit(rtapi_kmod_exit);
