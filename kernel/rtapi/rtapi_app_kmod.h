/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_app_kmod.h - the kernel flavor of rtapi_app.h: module parameters become
 * module_param/module_param_array, and module_init/module_exit call the component's
 * rtapi_app_main/rtapi_app_exit inside the HAL load context (hal_host.h), so
 * "show comp" names the module and its arguments and a failed or unloaded module
 * leaves no component behind. Included only through rtapi_app.h. */
#ifndef RTAPI_APP_KMOD_H
#define RTAPI_APP_KMOD_H

#include <linux/module.h>
#include <linux/moduleparam.h>
#include <linux/init.h>

/* Permission 0444: values readable under /sys/module/NAME/parameters, never changed
 * behind the component's back after init. */
#define RTAPI_MP_INT(var, descr) \
	module_param(var, int, 0444); MODULE_PARM_DESC(var, descr)
#define RTAPI_MP_LONG(var, descr) \
	module_param(var, long, 0444); MODULE_PARM_DESC(var, descr)
#define RTAPI_MP_STRING(var, descr) \
	module_param(var, charp, 0444); MODULE_PARM_DESC(var, descr)
/* 'num' is implied by the array's size, as in the other flavor. */
#define RTAPI_MP_ARRAY_INT(var, num, descr) \
	module_param_array(var, int, NULL, 0444); MODULE_PARM_DESC(var, descr)
#define RTAPI_MP_ARRAY_LONG(var, num, descr) \
	module_param_array(var, long, NULL, 0444); MODULE_PARM_DESC(var, descr)
#define RTAPI_MP_ARRAY_STRING(var, num, descr) \
	module_param_array(var, charp, NULL, 0444); MODULE_PARM_DESC(var, descr)

#define EXPORT_FUNCTION(fn) EXPORT_SYMBOL(fn)
#ifndef MODULE_SUPPORTED_DEVICE
#define MODULE_SUPPORTED_DEVICE(x)
#endif

/* A component's FP translation unit (comp's NAME_fp.o, -D__COMP_PART_FP) may declare
 * module parameters but is linked beside the glue that holds the module's init/exit. */
#ifndef __COMP_PART_FP_ONLY

/* From hal_host.h, declared here so that rtapi stays below hal in the include order. */
void hal_set_load_context(const char *module, const char *args);
void hal_set_load_module(void *owner);
int hal_exit_module_comps(const char *module);

/* The loadrt arguments as halcmd joined them, for "show comp" and "save": the
 * kernel's parser cuts THIS_MODULE->args apart in place, so halcmd (hal::kmod) passes
 * them once more in this parameter. Empty when loaded by hand with insmod. */
static char *hal_loadrt_args;
module_param(hal_loadrt_args, charp, 0);

static int __init rtapi_kmod_app_init(void)
{
	int rc;

	/* hal_lib serialises module inits and exits here (two insmods at once): the
	 * context says whose components and memory are being made. */
	hal_set_load_context(KBUILD_MODNAME, hal_loadrt_args ? hal_loadrt_args : "");
	hal_set_load_module(THIS_MODULE);
	rc = rtapi_app_main();
	if (rc) {
		/* halcmd finds this line in /proc/rtapi/messages and words it as the
		 * simulated flavor does (hal::kmod, kmod.cpp): keep the two in step. */
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: rtapi_app_main failed (%d)\n",
				KBUILD_MODNAME, rc);
		hal_exit_module_comps(KBUILD_MODNAME);
	}
	hal_set_load_context(NULL, NULL);
	return rc < 0 ? rc : rc ? -EINVAL : 0;
}

static void __exit rtapi_kmod_app_exit(void)
{
	hal_set_load_context(KBUILD_MODNAME, "");
	rtapi_app_exit();
	hal_exit_module_comps(KBUILD_MODNAME);
	hal_set_load_context(NULL, NULL);
}

module_init(rtapi_kmod_app_init);
module_exit(rtapi_kmod_app_exit);

#endif /* __COMP_PART_FP_ONLY */

#endif /* RTAPI_APP_KMOD_H */
