/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_parport_kmod.c - the kernel flavor's access to Linux parallel ports for
 * hal_parport_get (hal_parport.h). The parport calls themselves are in
 * rtapi_parport_linux.ko, which registers them here while it is loaded
 * (rtapi_parport_linux.h says why they cannot be in rtapi.ko). Without it Linux
 * drives no parallel port HAL can use: addresses are claimed as raw regions, and a
 * parport *number* is refused. */
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/slab.h>
#include "rtapi_kmod.h"
#include "hal_parport.h"
#include "rtapi_parport_linux.h"

static DEFINE_MUTEX(ops_lock);
static const struct rtapi_parport_linux_ops *linux_ops;

struct linux_claim {
	const struct rtapi_parport_linux_ops *ops;
	void *handle;
};

int rtapi_parport_linux_register(const struct rtapi_parport_linux_ops *ops)
{
	int rc = 0;

	mutex_lock(&ops_lock);
	if (linux_ops)
		rc = -EBUSY;
	else
		linux_ops = ops;
	mutex_unlock(&ops_lock);
	return rc;
}
EXPORT_SYMBOL(rtapi_parport_linux_register);

void rtapi_parport_linux_unregister(const struct rtapi_parport_linux_ops *ops)
{
	mutex_lock(&ops_lock);
	if (linux_ops == ops)
		linux_ops = NULL;
	mutex_unlock(&ops_lock);
}
EXPORT_SYMBOL(rtapi_parport_linux_unregister);

/* The registered operations with a reference on their module, or NULL. */
static const struct rtapi_parport_linux_ops *get_ops(void)
{
	const struct rtapi_parport_linux_ops *ops;

	mutex_lock(&ops_lock);
	ops = linux_ops;
	if (ops && !try_module_get(ops->owner))
		ops = NULL;
	mutex_unlock(&ops_lock);
	return ops;
}

int rtapi_parport_linux_claim(unsigned int which, int is_number, unsigned int modes,
			      const char *owner, unsigned short *base,
			      unsigned short *base_hi, void **handle)
{
	const struct rtapi_parport_linux_ops *ops = get_ops();
	struct linux_claim *claim;
	int rc;

	if (!ops) {
		if (!is_number)
			return 0;	/* no parport layer: Linux owns no parallel port */
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: parport %u: Linux parport support is "
				"not loaded (modprobe parport_pc), or give the port's address\n",
				which);
		return -ENODEV;
	}
	claim = kzalloc(sizeof(*claim), GFP_KERNEL);
	if (!claim) {
		module_put(ops->owner);
		return -ENOMEM;
	}
	rc = ops->claim(which, is_number, modes, owner, base, base_hi, &claim->handle);
	if (rc <= 0) {
		kfree(claim);
		module_put(ops->owner);
		return rc;
	}
	claim->ops = ops;
	*handle = claim;
	return 1;
}

void rtapi_parport_linux_release(void *handle)
{
	struct linux_claim *claim = handle;
	const struct rtapi_parport_linux_ops *ops = claim->ops;

	ops->release(claim->handle);
	kfree(claim);
	module_put(ops->owner);
}

EXPORT_SYMBOL(hal_parport_get);
EXPORT_SYMBOL(hal_parport_release);
