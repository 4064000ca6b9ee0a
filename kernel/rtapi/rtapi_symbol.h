/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_symbol.h - part of the RTAPI interface (with rtapi.h), in both flavors:
 * rtapi_symbol_kmod.c (kernel), user/rtapi_app/module_host.cpp (simulated). */
#ifndef RTAPI_SYMBOL_H
#define RTAPI_SYMBOL_H

#include "rtapi.h"

#ifdef __cplusplus
extern "C" {
#endif

/* --- symbols of other realtime modules, found at run time: init/cleanup code only ---
 * rtapi_symbol_get: the address of NAME, exported (EXPORT_SYMBOL) by a realtime module
 * that is loaded, or NULL. For a module that must call whichever of several
 * interchangeable modules is loaded (motmod and the kinematics modules): a direct
 * reference would bind it, in the kernel flavor's build, to one of them by name.
 * The exporting module then cannot be unloaded until rtapi_symbol_put(NAME) (kernel
 * flavor: symbol_get/symbol_put) or, in the simulated flavor, until the caller's own
 * module is unloaded; call both from rtapi_app_main / rtapi_app_exit. */
void *rtapi_symbol_get(const char *name);
void rtapi_symbol_put(const char *name);

#ifdef __cplusplus
}
#endif
#endif /* RTAPI_SYMBOL_H */
