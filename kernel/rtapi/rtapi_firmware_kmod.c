/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_firmware_kmod.c - rtapi_request_firmware (rtapi_firmware.h) in the kernel
 * flavor: the kernel's firmware loader, which wants a device; a root device named
 * after the request lives as long as the image is held. */
#include <linux/module.h>
#include <linux/device.h>
#include <linux/firmware.h>
#include <linux/slab.h>
#include "rtapi_kmod.h"
#include "rtapi_firmware.h"

struct fw_hold {
	struct rtapi_firmware pub;
	const struct firmware *fw;
	struct device *dev;
};

static int name_ok(const char *name)
{
	const char *p = name;

	if (!name || !*name || *name == '/')
		return 0;
	for (;;) {		/* no ".." component */
		if (p[0] == '.' && p[1] == '.' && (p[2] == '/' || !p[2]))
			return 0;
		p = strchr(p, '/');
		if (!p)
			return 1;
		p++;
	}
}

int rtapi_request_firmware(const struct rtapi_firmware **fw, const char *name)
{
	struct fw_hold *h;
	int rc;

	if (!name_ok(name)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: firmware name '%s' must be relative to "
				"/lib/firmware, without '..'\n", name ? name : "");
		return -EINVAL;
	}
	h = kzalloc(sizeof(*h), GFP_KERNEL);
	if (!h)
		return -ENOMEM;
	h->dev = root_device_register("rtapi_firmware");
	if (IS_ERR(h->dev)) {
		rc = PTR_ERR(h->dev);
		kfree(h);
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: firmware '%s': no device for the "
				"loader (%d)\n", name, rc);
		return rc;
	}
	rc = request_firmware_direct(&h->fw, name, h->dev);
	if (rc) {
		root_device_unregister(h->dev);
		kfree(h);
		if (rc != -ENOENT)
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: firmware '%s' cannot be read "
					"(%d)\n", name, rc);
		return rc;
	}
	h->pub.size = h->fw->size;
	h->pub.data = h->fw->data;
	h->pub.priv = h;
	*fw = &h->pub;
	return 0;
}
EXPORT_SYMBOL(rtapi_request_firmware);

void rtapi_release_firmware(const struct rtapi_firmware *fw)
{
	struct fw_hold *h;

	if (!fw)
		return;
	h = fw->priv;
	release_firmware(h->fw);
	root_device_unregister(h->dev);
	kfree(h);
}
EXPORT_SYMBOL(rtapi_release_firmware);
