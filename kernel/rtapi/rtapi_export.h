/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_export.h - EXPORT_SYMBOL for any file of a module, in both flavors. A module
 * built from several files exports its API from the files that define it, while
 * rtapi_app.h (module_init, module parameters) may be included only by the file
 * holding rtapi_app_main(). Kernel flavor: the kernel's EXPORT_SYMBOL (the symbol
 * becomes visible to modules loaded later). Simulated flavor: nothing to do,
 * rtapi_app dlopen()s every module with RTLD_GLOBAL. */
#ifndef RTAPI_EXPORT_H
#define RTAPI_EXPORT_H

#ifdef __KERNEL__
#include <linux/export.h>
#else
#ifndef EXPORT_SYMBOL
#define EXPORT_SYMBOL(sym)
#endif
#ifndef EXPORT_SYMBOL_GPL
#define EXPORT_SYMBOL_GPL(sym)
#endif
#endif

#endif /* RTAPI_EXPORT_H */
