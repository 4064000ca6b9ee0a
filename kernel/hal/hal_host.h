/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_host.h - calls the module host makes around a component's init and exit:
 * rtapi_app in the simulated flavor, the module loader glue in the kernel flavor.
 * Not for components. */
#ifndef HAL_HOST_H
#define HAL_HOST_H

#include "hal.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Components that call hal_init() until the next call are recorded as created by
 * 'module' loaded with 'args' (shown by "show comp", written by "save comp").
 * Pass NULL, NULL after rtapi_app_main() returns. Init code only. */
void hal_set_load_context(const char *module, const char *args);
/* Kernel flavor, right after hal_set_load_context(): the module's struct module, which
 * functions it exports hold a reference on while on a thread. */
void hal_set_load_module(void *owner);

/* Remove every component created by 'module' (after rtapi_app_exit(), or when
 * rtapi_app_main() failed and left some behind). Returns how many were removed. */
int hal_exit_module_comps(const char *module);

/* Realtime components plus threads in the segment (mapping it if needed). A host
 * that has not loaded anything yet finds only what a host before it left behind:
 * the simulated flavor's rtapi_app refuses to load on top of that (issue 19, item 2).
 * Returns the count or -errno. */
int hal_realtime_object_count(void);

/* Delete every thread (their tasks stop first): when the realtime host shuts
 * down, since threads outlive the modules that created them. Returns how many. */
int hal_exit_threads(void);
/* Threads that exist now (the host keeps running while any do). */
int hal_thread_count(void);

/* Call 'cb' for each thread with its period and the periods it missed since it was
 * created, so the host can warn when they grow. Returns how many, or -errno. */
int hal_thread_overruns(void (*cb)(const char *name, long long period_ns,
				   unsigned long long overruns, void *ctx), void *ctx);

#ifdef __cplusplus
}
#endif
#endif /* HAL_HOST_H */
