/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_parport_kmod.c - the kernel flavor's access to Linux parallel ports for
 * hal_parport_get (hal_parport.h). The parport core is a module that is often not
 * loaded (and rtapi.ko must load without it), so its functions are taken with
 * symbol_get when a port is requested: without it Linux owns no parallel port, and
 * addresses are claimed as raw regions; a parport *number* then needs it loaded. */
#include <linux/module.h>
#include <linux/parport.h>
#include <linux/slab.h>
#include "rtapi_kmod.h"
#include "hal_parport.h"

struct linux_pp {
	struct parport *(*find_number)(int);
	struct parport *(*find_base)(unsigned long);
	void (*put_port)(struct parport *);
	struct pardevice *(*register_dev)(struct parport *, const char *,
					  const struct pardev_cb *, int);
	void (*unregister_dev)(struct pardevice *);
	int (*claim)(struct pardevice *);
	void (*release)(struct pardevice *);
	struct pardevice *dev;
};

static void put_symbols(struct linux_pp *pp)
{
	if (pp->find_number) symbol_put(parport_find_number);
	if (pp->find_base) symbol_put(parport_find_base);
	if (pp->put_port) symbol_put(parport_put_port);
	if (pp->register_dev) symbol_put(parport_register_dev_model);
	if (pp->unregister_dev) symbol_put(parport_unregister_device);
	if (pp->claim) symbol_put(parport_claim);
	if (pp->release) symbol_put(parport_release);
}

/* 1 when every parport function was found (module references held). */
static int get_symbols(struct linux_pp *pp)
{
	pp->find_number = symbol_get(parport_find_number);
	pp->find_base = symbol_get(parport_find_base);
	pp->put_port = symbol_get(parport_put_port);
	pp->register_dev = symbol_get(parport_register_dev_model);
	pp->unregister_dev = symbol_get(parport_unregister_device);
	pp->claim = symbol_get(parport_claim);
	pp->release = symbol_get(parport_release);
	if (pp->find_number && pp->find_base && pp->put_port && pp->register_dev &&
	    pp->unregister_dev && pp->claim && pp->release)
		return 1;
	put_symbols(pp);
	return 0;
}

int rtapi_parport_linux_claim(unsigned int which, int is_number, unsigned int modes,
			      const char *owner, unsigned short *base,
			      unsigned short *base_hi, void **handle)
{
	struct pardev_cb cb = { .flags = PARPORT_FLAG_EXCL };
	struct linux_pp *pp = kzalloc(sizeof(*pp), GFP_KERNEL);
	struct parport *port;
	int rc;

	if (!pp)
		return -ENOMEM;
	if (!get_symbols(pp)) {
		kfree(pp);
		if (!is_number)
			return 0;	/* no parport core: Linux owns no parallel port */
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: parport %u: Linux parport support is "
				"not loaded (modprobe parport_pc), or give the port's address\n",
				which);
		return -ENODEV;
	}
	port = is_number ? pp->find_number(which) : pp->find_base(which);
	if (!port) {
		put_symbols(pp);
		kfree(pp);
		if (!is_number)
			return 0;
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: Linux has no parport %u\n", which);
		return -ENODEV;
	}
	if ((port->modes & modes) != modes)
		rtapi_print_msg(RTAPI_MSG_WARN, "hal_parport: parport at 0x%lx lacks some requested "
				"modes (0x%x of 0x%x); continuing\n", port->base,
				port->modes & modes, modes);
	pp->dev = pp->register_dev(port, owner, &cb, 0);
	rc = pp->dev ? pp->claim(pp->dev) : -EBUSY;
	if (rc) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: parport at 0x%lx is busy (used by "
				"another driver)\n", port->base);
		if (pp->dev)
			pp->unregister_dev(pp->dev);
		pp->put_port(port);
		put_symbols(pp);
		kfree(pp);
		return -EBUSY;
	}
	*base = port->base;
	*base_hi = port->base_hi;
	pp->put_port(port);	/* the registered device holds its own reference */
	*handle = pp;
	return 1;
}

void rtapi_parport_linux_release(void *handle)
{
	struct linux_pp *pp = handle;

	pp->release(pp->dev);
	pp->unregister_dev(pp->dev);
	put_symbols(pp);
	kfree(pp);
}

EXPORT_SYMBOL(hal_parport_get);
EXPORT_SYMBOL(hal_parport_release);
