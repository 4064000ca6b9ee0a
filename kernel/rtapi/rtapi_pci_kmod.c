/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_pci_kmod.c - rtapi_pci.h in the kernel flavor. rtapi_pci_map_bar: a simulated
 * card if one is registered, else pci_get_device, pci_enable_device,
 * pci_request_region (so that no other driver shares the card) and pci_iomap of the
 * whole BAR. rtapi_pci_register_driver: the simulated cards first, then a pci_driver
 * whose table holds the driver's IDs; each bound card is enabled, its regions
 * requested, and BARs are mapped on demand with pci_iomap (memory or I/O: ioread32
 * and iowrite8 serve both). */
#include <linux/module.h>
#include <linux/pci.h>
#include <linux/slab.h>
#include "rtapi_kmod.h"
#include "rtapi_pci.h"

struct rtapi_pci_bar {
	int sim;		/* simulated card's handle, or -1 */
	int bar;
	unsigned long len;
	void __iomem *mem;
	struct pci_dev *pdev;
	int own_region;		/* rtapi_pci_map_bar: the region and device are ours */
};

struct rtapi_pci_dev {
	struct rtapi_pci_driver *drv;
	int sim;		/* simulated card's handle, or -1 */
	struct pci_dev *pdev;
	void *drvdata;
	char name[40];
};

/* rtapi's side of one registered driver */
struct pci_glue {
	struct pci_driver pd;
	struct pci_device_id *table;
	struct rtapi_pci_driver *drv;
	struct rtapi_pci_dev *sim[RTAPI_PCISIM_MAX];
	int taken, first_err;
};

int rtapi_pci_map_bar(unsigned int vendor, unsigned int device, int index, int bar,
		      const char *owner, struct rtapi_pci_bar **map)
{
	struct rtapi_pci_bar *m = kzalloc(sizeof(*m), GFP_KERNEL);
	struct pci_dev *pdev = NULL;
	int skipped = 0, rc;

	if (!m)
		return -ENOMEM;
	m->own_region = 1;
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
	m->own_region = 1;
	*map = m;
	return 0;
}
EXPORT_SYMBOL(rtapi_pci_map_bar);

void rtapi_pci_unmap_bar(struct rtapi_pci_bar *m)
{
	if (m->sim >= 0) {
		if (m->own_region)
			rtapi_pcisim_release(m->sim);
	} else {
		pci_iounmap(m->pdev, m->mem);
		if (m->own_region) {
			pci_release_region(m->pdev, m->bar);
			pci_disable_device(m->pdev);
			pci_dev_put(m->pdev);
		}
	}
	kfree(m);
}
EXPORT_SYMBOL(rtapi_pci_unmap_bar);

/* size 4 or 1: ioread32/iowrite32 or ioread8/iowrite8 (memory or port cookies) */
static rtapi_u32 bar_read(struct rtapi_pci_bar *m, unsigned long offset, int size)
{
	if (m->sim >= 0)
		return rtapi_pcisim_read(m->sim, m->bar, offset, size);
	if (offset + size > m->len)
		return size == 4 ? ~0u : 0xff;
	return size == 4 ? ioread32(m->mem + offset) : ioread8(m->mem + offset);
}

static void bar_write(struct rtapi_pci_bar *m, unsigned long offset, int size, rtapi_u32 value)
{
	if (m->sim >= 0)
		rtapi_pcisim_write(m->sim, m->bar, offset, size, value);
	else if (offset + size > m->len)
		return;
	else if (size == 4)
		iowrite32(value, m->mem + offset);
	else
		iowrite8((u8)value, m->mem + offset);
}

rtapi_u32 rtapi_pci_readl(struct rtapi_pci_bar *m, unsigned long offset)
{
	return bar_read(m, offset, 4);
}
EXPORT_SYMBOL(rtapi_pci_readl);

void rtapi_pci_writel(struct rtapi_pci_bar *m, unsigned long offset, rtapi_u32 value)
{
	bar_write(m, offset, 4, value);
}
EXPORT_SYMBOL(rtapi_pci_writel);

rtapi_u8 rtapi_pci_readb(struct rtapi_pci_bar *m, unsigned long offset)
{
	return (rtapi_u8)bar_read(m, offset, 1);
}
EXPORT_SYMBOL(rtapi_pci_readb);

void rtapi_pci_writeb(struct rtapi_pci_bar *m, unsigned long offset, rtapi_u8 value)
{
	bar_write(m, offset, 1, value);
}
EXPORT_SYMBOL(rtapi_pci_writeb);

/* --- drivers --- */

static int call_probe(struct pci_glue *g, struct rtapi_pci_dev *d, int which)
{
	int rc;

	d->drv = g->drv;
	rc = g->drv->probe(d, &g->drv->ids[which]);
	if (rc < 0 && !g->first_err)
		g->first_err = rc;
	if (rc == 0)
		g->taken++;
	return rc;
}

static int glue_probe(struct pci_dev *pdev, const struct pci_device_id *id)
{
	struct pci_glue *g = container_of(to_pci_driver(pdev->dev.driver), struct pci_glue, pd);
	struct rtapi_pci_dev *d = kzalloc(sizeof(*d), GFP_KERNEL);
	int rc;

	if (!d)
		return -ENOMEM;
	d->sim = -1;
	d->pdev = pdev;
	snprintf(d->name, sizeof(d->name), "%s", pci_name(pdev));
	rc = pci_enable_device(pdev);
	if (!rc) {
		rc = pci_request_regions(pdev, g->drv->name);
		if (rc)
			pci_disable_device(pdev);
	}
	if (rc) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: PCI card %s is busy or cannot be enabled (%d)\n",
				pci_name(pdev), rc);
		if (!g->first_err)
			g->first_err = rc;
		kfree(d);
		return rc;
	}
	pci_set_drvdata(pdev, d);
	rc = call_probe(g, d, (int)id->driver_data);
	if (rc) {
		pci_set_drvdata(pdev, NULL);
		pci_release_regions(pdev);
		pci_disable_device(pdev);
		kfree(d);
		return rc < 0 ? rc : -ENODEV;
	}
	return 0;
}

static void glue_remove(struct pci_dev *pdev)
{
	struct pci_glue *g = container_of(to_pci_driver(pdev->dev.driver), struct pci_glue, pd);
	struct rtapi_pci_dev *d = pci_get_drvdata(pdev);

	g->drv->remove(d);
	pci_set_drvdata(pdev, NULL);
	pci_release_regions(pdev);
	pci_disable_device(pdev);
	kfree(d);
}

static void remove_sim(struct pci_glue *g)
{
	int i;

	for (i = 0; i < RTAPI_PCISIM_MAX; i++)
		if (g->sim[i]) {
			g->drv->remove(g->sim[i]);
			rtapi_pcisim_release(g->sim[i]->sim);
			kfree(g->sim[i]);
			g->sim[i] = NULL;
		}
}

/* the simulated cards, in slot order */
static int probe_sim(struct pci_glue *g)
{
	int h = -1, which, rc;

	while ((h = rtapi_pcisim_claim_match(g->drv->ids, h + 1, g->drv->name, &which)) >= 0) {
		struct rtapi_pci_dev *d = kzalloc(sizeof(*d), GFP_KERNEL);

		if (!d) {
			rtapi_pcisim_release(h);
			return -ENOMEM;
		}
		d->sim = h;
		snprintf(d->name, sizeof(d->name), "sim:%s", rtapi_pcisim_name(h));
		rc = call_probe(g, d, which);
		if (rc) {
			rtapi_pcisim_release(h);
			kfree(d);
			if (rc < 0)
				return rc;
			continue;
		}
		g->sim[h] = d;
	}
	return 0;
}

int rtapi_pci_register_driver(struct rtapi_pci_driver *drv)
{
	struct pci_glue *g = kzalloc(sizeof(*g), GFP_KERNEL);
	int n, i, rc;

	if (!g)
		return -ENOMEM;
	for (n = 0; drv->ids[n].vendor; n++)
		;
	g->table = kcalloc(n + 1, sizeof(*g->table), GFP_KERNEL);
	if (!g->table) {
		kfree(g);
		return -ENOMEM;
	}
	for (i = 0; i < n; i++) {
		g->table[i].vendor = drv->ids[i].vendor;
		g->table[i].device = drv->ids[i].device;
		g->table[i].subvendor = drv->ids[i].subvendor;
		g->table[i].subdevice = drv->ids[i].subdevice;
		g->table[i].driver_data = i;
	}
	g->drv = drv;
	drv->rtapi = g;
	g->pd.name = drv->name;
	g->pd.id_table = g->table;
	g->pd.probe = glue_probe;
	g->pd.remove = glue_remove;
	rc = probe_sim(g);
	if (rc) {
		remove_sim(g);
		goto fail;
	}
	/* probes run synchronously in here, for the cards already present */
	rc = pci_register_driver(&g->pd);
	if (rc) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: %s: cannot register the PCI driver (%d)\n",
				drv->name, rc);
		remove_sim(g);
		goto fail;
	}
	if (g->first_err) {
		rc = g->first_err;
		rtapi_pci_unregister_driver(drv);
		return rc;
	}
	return g->taken;
fail:
	kfree(g->table);
	kfree(g);
	drv->rtapi = NULL;
	return rc;
}
EXPORT_SYMBOL(rtapi_pci_register_driver);

void rtapi_pci_unregister_driver(struct rtapi_pci_driver *drv)
{
	struct pci_glue *g = drv->rtapi;

	if (!g)
		return;
	pci_unregister_driver(&g->pd);
	remove_sim(g);
	kfree(g->table);
	kfree(g);
	drv->rtapi = NULL;
}
EXPORT_SYMBOL(rtapi_pci_unregister_driver);

int rtapi_pci_dev_map_bar(struct rtapi_pci_dev *d, int bar, struct rtapi_pci_bar **map)
{
	struct rtapi_pci_bar *m = kzalloc(sizeof(*m), GFP_KERNEL);

	if (!m)
		return -ENOMEM;
	m->bar = bar;
	m->sim = d->sim;
	if (d->sim >= 0) {
		m->len = rtapi_pcisim_bar_len(d->sim, bar);
	} else if (bar >= 0 && bar < RTAPI_PCI_BARS && pci_resource_len(d->pdev, bar)) {
		m->pdev = d->pdev;
		m->len = pci_resource_len(d->pdev, bar);
		m->mem = pci_iomap(d->pdev, bar, 0);
	}
	if (!m->len || (d->sim < 0 && !m->mem)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: PCI card %s: cannot map BAR%d\n", d->name, bar);
		kfree(m);
		return -EIO;
	}
	*map = m;
	return 0;
}
EXPORT_SYMBOL(rtapi_pci_dev_map_bar);

const char *rtapi_pci_dev_name(const struct rtapi_pci_dev *d)
{
	return d->name;
}
EXPORT_SYMBOL(rtapi_pci_dev_name);

void rtapi_pci_set_drvdata(struct rtapi_pci_dev *d, void *data)
{
	d->drvdata = data;
}
EXPORT_SYMBOL(rtapi_pci_set_drvdata);

void *rtapi_pci_get_drvdata(const struct rtapi_pci_dev *d)
{
	return d->drvdata;
}
EXPORT_SYMBOL(rtapi_pci_get_drvdata);

EXPORT_SYMBOL(rtapi_pcisim_register);
EXPORT_SYMBOL(rtapi_pcisim_register_card);
EXPORT_SYMBOL(rtapi_pcisim_unregister);
