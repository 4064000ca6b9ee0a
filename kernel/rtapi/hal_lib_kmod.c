/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_lib_kmod.c - hal_lib.ko's init/exit and exports (kernel flavor). The HAL core
 * files are flavor independent; this file makes them one module: it keeps the HAL
 * segment mapped while hal_lib.ko is loaded, so userspace tools find it from the
 * first loadrt on, and exports the HAL API to components. */
#include <linux/module.h>
#include "hal_internal.h"
#include "hal_host.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("HAL: the hardware abstraction layer's realtime library");

static int __init hal_lib_kmod_init(void)
{
	int rc = hal_segment_map();

	if (rc)
		return rc;
	hal_local_users++;	/* our own hold: components come and go */
	return 0;
}

static void __exit hal_lib_kmod_exit(void)
{
	hal_exit_threads();	/* threads outlive their modules, not hal_lib.ko */
	hal_local_users = 0;
	hal_segment_unmap();
}

module_init(hal_lib_kmod_init);
module_exit(hal_lib_kmod_exit);

EXPORT_SYMBOL(hal_init);
EXPORT_SYMBOL(hal_exit);
EXPORT_SYMBOL(hal_ready);
EXPORT_SYMBOL(hal_malloc);
EXPORT_SYMBOL(hal_set_constructor);
EXPORT_SYMBOL(hal_set_load_context);
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
