/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_parport_linux.c - the module rtapi_parport_linux.ko: claims parallel ports
 * that Linux's parport layer drives, for rtapi.ko's hal_parport_get (small-boards.md
 * 3.5: by parport number or by base address, a registered pardevice claimed for
 * exclusive use). It links against parport.ko, which is why it is not part of
 * rtapi.ko (rtapi_parport_linux.h). Kernel flavor only. */
#include <linux/module.h>
#include <linux/parport.h>
#include <linux/slab.h>
#include "rtapi.h"
#include "rtapi_parport_linux.h"

static int pp_claim(unsigned int which, int is_number, unsigned int modes, const char *owner,
		    unsigned short *base, unsigned short *base_hi, void **handle)
{
	struct pardev_cb cb = { .flags = PARPORT_FLAG_EXCL };
	struct parport *port = is_number ? parport_find_number(which) : parport_find_base(which);
	struct pardevice *dev;

	if (!port) {
		if (!is_number)
			return 0;	/* not a port Linux drives: raw regions */
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: Linux has no parport %u\n", which);
		return -ENODEV;
	}
	if ((port->modes & modes) != modes)
		rtapi_print_msg(RTAPI_MSG_WARN, "hal_parport: parport at 0x%lx lacks some requested "
				"modes (0x%x of 0x%x); continuing\n", port->base,
				port->modes & modes, modes);
	dev = parport_register_dev_model(port, owner, &cb, 0);
	if (!dev || parport_claim(dev)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: parport at 0x%lx is busy (used by "
				"another driver)\n", port->base);
		if (dev)
			parport_unregister_device(dev);
		parport_put_port(port);
		return -EBUSY;
	}
	*base = port->base;
	*base_hi = port->base_hi <= 0xffff ? port->base_hi : 0;
	parport_put_port(port);	/* the registered device holds its own reference */
	*handle = dev;
	return 1;
}

static void pp_release(void *handle)
{
	struct pardevice *dev = handle;

	parport_release(dev);
	parport_unregister_device(dev);
}

static const struct rtapi_parport_linux_ops ops = {
	.owner = THIS_MODULE,
	.claim = pp_claim,
	.release = pp_release,
};

static int __init pp_init(void)
{
	return rtapi_parport_linux_register(&ops);
}

static void __exit pp_exit(void)
{
	rtapi_parport_linux_unregister(&ops);
}

module_init(pp_init);
module_exit(pp_exit);
MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("RTAPI: parallel ports owned by Linux's parport layer, for hal_parport_get");
