/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_symbol_kmod.c - rtapi_symbol_get/put (rtapi.h) in the kernel flavor: the
 * kernel's symbol_get, which finds an exported symbol of a loaded module by name and
 * holds that module (rmmod then says it is in use) until symbol_put. No reference to
 * the symbol is linked in, so modpost records no dependency on its exporter. */
#include <linux/module.h>

#include "rtapi_symbol.h"

void *rtapi_symbol_get(const char *name)
{
	return __symbol_get(name);
}
EXPORT_SYMBOL(rtapi_symbol_get);

void rtapi_symbol_put(const char *name)
{
	__symbol_put(name);
}
EXPORT_SYMBOL(rtapi_symbol_put);
