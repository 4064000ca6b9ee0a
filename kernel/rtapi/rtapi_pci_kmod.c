/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_pci_kmod.c - rtapi_pci.h in the kernel flavor: a simulated card if one is
 * registered, else pci_get_device, pci_enable_device, pci_request_region (so that no
 * other driver shares the card) and pci_iomap of the whole BAR. */
#include <linux/module.h>
#include <linux/pci.h>
#include <linux/slab.h>
#include "rtapi_kmod.h"
#include "rtapi_pci.h"

struct rtapi_pci_bar {
	int sim;		/* simulated card's handle, or -1 */
	unsigned long len;
	void __iomem *mem;
	struct pci_dev *pdev;
	int bar;
};

int rtapi_pci_map_bar(unsigned int vendor, unsigned int device, int index, int bar,
		      const char *owner, struct rtapi_pci_bar **map)
{
	struct rtapi_pci_bar *m = kzalloc(sizeof(*m), GFP_KERNEL);
	struct pci_dev *pdev = NULL;
	int skipped = 0, rc;

	if (!m)
		return -ENOMEM;
	m->sim = rtapi_pcisim_claim(vendor, device, index, owner, &skipped, &m->len);
	if (m->sim >= 0 || m->sim == -EBUSY) {
		rc = m->sim;
		if (rc < 0)
			kfree(m);
		else
			*map = m;
		return rc < 0 ? rc : 0;
	}
	index -= skipped;
	do
		pdev = pci_get_device(vendor, device, pdev);
	while (pdev && index-- > 0);
	if (!pdev) {
		kfree(m);
		return -ENODEV;
	}
	rc = pci_enable_device(pdev);
	if (!rc) {
		rc = pci_request_region(pdev, bar, owner);
		if (rc)
			pci_disable_device(pdev);
	}
	if (rc) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: PCI card %s (%04x:%04x) BAR%d is busy or "
				"cannot be enabled (%d)\n", pci_name(pdev), vendor, device, bar, rc);
		pci_dev_put(pdev);
		kfree(m);
		return rc;
	}
	m->mem = pci_iomap(pdev, bar, 0);
	if (!m->mem) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: PCI card %s: cannot map BAR%d\n",
				pci_name(pdev), bar);
		pci_release_region(pdev, bar);
		pci_disable_device(pdev);
		pci_dev_put(pdev);
		kfree(m);
		return -EIO;
	}
	m->len = pci_resource_len(pdev, bar);
	m->pdev = pdev;
	m->bar = bar;
	*map = m;
	return 0;
}
EXPORT_SYMBOL(rtapi_pci_map_bar);

void rtapi_pci_unmap_bar(struct rtapi_pci_bar *m)
{
	if (m->sim >= 0) {
		rtapi_pcisim_release(m->sim);
	} else {
		pci_iounmap(m->pdev, m->mem);
		pci_release_region(m->pdev, m->bar);
		pci_disable_device(m->pdev);
		pci_dev_put(m->pdev);
	}
	kfree(m);
}
EXPORT_SYMBOL(rtapi_pci_unmap_bar);

rtapi_u32 rtapi_pci_readl(struct rtapi_pci_bar *m, unsigned long offset)
{
	if (m->sim >= 0)
		return rtapi_pcisim_readl(m->sim, offset);
	return offset + 4 <= m->len ? ioread32(m->mem + offset) : ~0u;
}
EXPORT_SYMBOL(rtapi_pci_readl);

void rtapi_pci_writel(struct rtapi_pci_bar *m, unsigned long offset, rtapi_u32 value)
{
	if (m->sim >= 0)
		rtapi_pcisim_writel(m->sim, offset, value);
	else if (offset + 4 <= m->len)
		iowrite32(value, m->mem + offset);
}
EXPORT_SYMBOL(rtapi_pci_writel);

EXPORT_SYMBOL(rtapi_pcisim_register);
EXPORT_SYMBOL(rtapi_pcisim_unregister);
