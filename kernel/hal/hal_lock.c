/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_lock.c - the HAL mutex (configuration changes) and the lock levels of
 * hal_set_lock(3hal). Realtime threads never take the mutex. */
#include "hal_internal.h"

void hal_lock(void)
{
	rtapi_mutex_get(&hal_seg->mutex);
}

void hal_unlock(void)
{
	rtapi_mutex_give(&hal_seg->mutex);
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

int hal_set_lock(unsigned char lock_type)
{
	if (!hal_seg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_set_lock: HAL is not initialised\n");
		return -EINVAL;
	}
	hal_seg->lock_level = lock_type;
	return 0;
}

int hal_get_lock(void)
{
	if (!hal_seg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_get_lock: HAL is not initialised\n");
		return -EINVAL;
	}
	return (int)hal_seg->lock_level;
}
