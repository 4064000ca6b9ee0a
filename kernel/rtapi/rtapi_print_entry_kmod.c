/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_print_entry_kmod.c - the variadic entry points of rtapi_print(3rtapi) and
 * rtapi_snprintf(3rtapi) in the kernel flavor. x86-64 passes double arguments of a
 * variadic call in SSE registers, and only a function compiled with SSE saves them
 * for va_arg, so kernel/Kbuild compiles this file like the FP files. The prologue
 * touches SSE registers only when the caller passed some (%al != 0), that is when
 * the caller is FP code inside an FPU section; the work happens in
 * rtapi_print_kmod.c, which opens an FPU section itself when needed. Nothing else
 * may go into this file. */
#include <linux/module.h>
#include <linux/kernel.h>
#include "rtapi_kmod.h"

int rtapi_snprintf(char *buf, unsigned long int size, const char *fmt, ...)
{
	va_list ap;
	int n;

	va_start(ap, fmt);
	n = rtapi_vsnprintf(buf, size, fmt, ap);
	va_end(ap);
	return n;
}
EXPORT_SYMBOL(rtapi_snprintf);

void rtapi_print(const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	rtapi_vprint_msg_kmod(RTAPI_MSG_ALL, fmt, ap);
	va_end(ap);
}
EXPORT_SYMBOL(rtapi_print);

void rtapi_print_msg(int level, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	rtapi_vprint_msg_kmod(level, fmt, ap);
	va_end(ap);
}
EXPORT_SYMBOL(rtapi_print_msg);
