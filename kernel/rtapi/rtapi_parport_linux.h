/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_parport_linux.h - how rtapi.ko reaches Linux's parport layer (kernel flavor
 * only). parport.ko exports its functions with EXPORT_SYMBOL, and symbol_get() only
 * resolves EXPORT_SYMBOL_GPL ones (Linux 6.1.53 and later), so rtapi.ko cannot look
 * them up itself; and linking against them would make rtapi.ko need parport.ko.
 * rtapi_parport_linux.ko (parport_linux/) links against parport and hands rtapi.ko
 * these operations while it is loaded; halcmd's loadrt inserts it before a module
 * that imports hal_parport_get when parport is loaded (user/kmod/kmod_modules.cpp). */
#ifndef RTAPI_PARPORT_LINUX_H
#define RTAPI_PARPORT_LINUX_H

struct module;

struct rtapi_parport_linux_ops {
	struct module *owner;	/* held while a port is claimed through it */
	/* rtapi_parport_linux_claim()'s contract (hal_parport.h) */
	int (*claim)(unsigned int which, int is_number, unsigned int modes,
		     const char *owner, unsigned short *base, unsigned short *base_hi,
		     void **handle);
	void (*release)(void *handle);
};

/* -EBUSY when another set is registered. */
int rtapi_parport_linux_register(const struct rtapi_parport_linux_ops *ops);
void rtapi_parport_linux_unregister(const struct rtapi_parport_linux_ops *ops);

#endif /* RTAPI_PARPORT_LINUX_H */
