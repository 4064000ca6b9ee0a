/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_print_kmod.c - messages through printk (rtapi_print(3rtapi)), and the
 * FPU-safe entry to the shared formatter, in the kernel flavor. */
#include <linux/module.h>
#include <linux/kernel.h>
#include <linux/printk.h>
#include <asm/fpu/api.h>
#include "rtapi_kmod.h"

static int msg_level = RTAPI_MSG_ERR;
module_param(msg_level, int, 0644);
MODULE_PARM_DESC(msg_level, "RTAPI message level, 0 (none) .. 5 (all), default 1 (errors)");

static rtapi_msg_handler_t msg_handler;

/* rtapi_format.c is compiled with SSE enabled and its entry points renamed to these
 * (see kernel/Kbuild): gcc may use SSE registers anywhere in that file, so every
 * call must sit inside a kernel FPU section. */
int rtapi_vsnprintf_fpu(char *buf, unsigned long int size, const char *fmt, va_list ap);

int rtapi_vsnprintf(char *buf, unsigned long int size, const char *fmt, va_list ap)
{
	int n;

	/* false inside a kernel FPU section already (a uses_fp task's cycle): the
	 * registers are ours there, and FPU sections must not nest. */
	if (!irq_fpu_usable())
		return rtapi_vsnprintf_fpu(buf, size, fmt, ap);
	kernel_fpu_begin();
	n = rtapi_vsnprintf_fpu(buf, size, fmt, ap);
	kernel_fpu_end();
	return n;
}
EXPORT_SYMBOL(rtapi_vsnprintf);

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

static void default_handler(msg_level_t level, const char *msg)
{
	switch (level) {
	case RTAPI_MSG_ERR: printk(KERN_ERR "%s", msg); break;
	case RTAPI_MSG_WARN: printk(KERN_WARNING "%s", msg); break;
	case RTAPI_MSG_INFO: printk(KERN_INFO "%s", msg); break;
	default: printk(KERN_DEBUG "%s", msg); break;
	}
}

static void emit(msg_level_t level, const char *fmt, va_list ap)
{
	char buf[256];	/* printk truncates long lines anyway */
	rtapi_msg_handler_t h = READ_ONCE(msg_handler);

	rtapi_vsnprintf(buf, sizeof(buf), fmt, ap);
	(h ? h : default_handler)(level, buf);
}

void rtapi_print(const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	emit(RTAPI_MSG_ALL, fmt, ap);
	va_end(ap);
}
EXPORT_SYMBOL(rtapi_print);

void rtapi_print_msg(int level, const char *fmt, ...)
{
	va_list ap;

	if (level <= RTAPI_MSG_NONE || level > READ_ONCE(msg_level))
		return;
	va_start(ap, fmt);
	emit(level, fmt, ap);
	va_end(ap);
}
EXPORT_SYMBOL(rtapi_print_msg);

int rtapi_set_msg_level(int level)
{
	if (level < RTAPI_MSG_NONE || level > RTAPI_MSG_ALL)
		return -EINVAL;
	WRITE_ONCE(msg_level, level);
	return 0;
}
EXPORT_SYMBOL(rtapi_set_msg_level);

int rtapi_get_msg_level(void)
{
	return READ_ONCE(msg_level);
}
EXPORT_SYMBOL(rtapi_get_msg_level);

void rtapi_set_msg_handler(rtapi_msg_handler_t handler)
{
	WRITE_ONCE(msg_handler, handler);
}
EXPORT_SYMBOL(rtapi_set_msg_handler);

rtapi_msg_handler_t rtapi_get_msg_handler(void)
{
	return READ_ONCE(msg_handler);
}
EXPORT_SYMBOL(rtapi_get_msg_handler);
