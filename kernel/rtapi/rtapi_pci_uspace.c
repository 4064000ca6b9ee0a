/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_pci_uspace.c - rtapi_pci.h in the simulated flavor: a simulated card if one
 * is registered, else the card's /sys/bus/pci/devices/<addr>/resourceN (root only):
 * memory BARs mapped with mmap, I/O BARs read and written with pread/pwrite (the
 * kernel does the inl/outb). A card is locked with flock so that a second driver is
 * refused. Cards are taken in the sorted order of their PCI addresses, as the
 * kernel scans them. */
#include <dirent.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include "rtapi.h"
#include "rtapi_pci.h"

/* where the cards are: sysfs, or (tests) a directory of the same layout named by
 * HAL_PCI_SYSFS_DIR, whose plain files stand in for the resource files */
static const char *sys_pci(void)
{
	const char *d = getenv("HAL_PCI_SYSFS_DIR");

	return d && *d ? d : "/sys/bus/pci/devices";
}

struct rtapi_pci_bar {
	int sim;		/* simulated card's handle, or -1 */
	int bar;
	unsigned long len;
	volatile unsigned char *mem;	/* memory BAR; NULL for an I/O BAR (fd) */
	int fd;
	int own;		/* rtapi_pci_map_bar: the card is ours to release */
};

struct rtapi_pci_dev {
	int sim;		/* simulated card's handle, or -1 */
	char addr[260];		/* sysfs name of a real card */
	int lock_fd;		/* its config file, flock()ed */
	void *drvdata;
	char name[280];
};

#define MAX_DEVS 16
struct pci_glue {		/* rtapi's side of one registered driver */
	struct rtapi_pci_dev *dev[MAX_DEVS];
	int n;
};

static unsigned int read_hex(const char *dev, const char *file)
{
	char path[512];
	unsigned int v = 0;
	FILE *f;

	snprintf(path, sizeof(path), "%s/%s/%s", sys_pci(), dev, file);
	f = fopen(path, "r");
	if (f) {
		if (fscanf(f, "%x", &v) != 1)
			v = 0;
		fclose(f);
	}
	return v;
}

static int by_name(const struct dirent **a, const struct dirent **b)
{
	return strcmp((*a)->d_name, (*b)->d_name);
}

/* The PCI address of the index-th card with these IDs into 'addr', or 0. */
static int find_card(unsigned int vendor, unsigned int device, int index, char *addr,
		     unsigned long size)
{
	struct dirent **list;
	int n, i, found = 0;

	n = scandir(sys_pci(), &list, 0, by_name);
	for (i = 0; i < n; i++) {
		const char *d = list[i]->d_name;

		if (!found && d[0] != '.' && read_hex(d, "vendor") == vendor &&
		    read_hex(d, "device") == device && index-- == 0) {
			snprintf(addr, size, "%s", d);
			found = 1;
		}
		free(list[i]);
	}
	if (n >= 0)
		free(list);
	return found;
}

static int bar_is_io(const char *addr, int bar);

/* resourceN of the card at addr into m: fd and len; a memory BAR also mapped */
static int open_resource(const char *addr, int bar, int io, struct rtapi_pci_bar *m)
{
	char path[512];
	struct stat st;
	void *mem;
	int e;

	snprintf(path, sizeof(path), "%s/%s/resource%d", sys_pci(), addr, bar);
	m->fd = open(path, O_RDWR | O_SYNC | O_CLOEXEC);
	if (m->fd < 0 || fstat(m->fd, &st) < 0 || st.st_size <= 0) {
		e = m->fd < 0 ? errno : EINVAL;
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: PCI card %s BAR%d: cannot open %s: %s "
				"(needs root, or group hal for a Mesa 5i24/5i25/6i25 with firmware/udev/60-hal.rules)\n", addr, bar, path, strerror(e));
		if (m->fd >= 0)
			close(m->fd);
		return -EPERM;
	}
	m->len = st.st_size;
	if (io)
		return 0;
	mem = mmap(0, st.st_size, PROT_READ | PROT_WRITE, MAP_SHARED, m->fd, 0);
	if (mem == MAP_FAILED) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: PCI card %s: cannot map BAR%d: %s\n", addr, bar,
				strerror(errno));
		close(m->fd);
		return -EIO;
	}
	m->mem = mem;
	return 0;
}

int rtapi_pci_map_bar(unsigned int vendor, unsigned int device, int index, int bar,
		      const char *owner, struct rtapi_pci_bar **map)
{
	struct rtapi_pci_bar *m = calloc(1, sizeof(*m));
	char addr[260];
	int skipped = 0, rc;

	if (!m)
		return -ENOMEM;
	m->own = 1;
	m->bar = bar;
	m->sim = rtapi_pcisim_claim(vendor, device, index, owner, &skipped, &m->len);
	if (m->sim >= 0) {
		*map = m;
		return 0;
	}
	if (m->sim == -EBUSY || !find_card(vendor, device, index - skipped, addr, sizeof(addr))) {
		rc = m->sim == -EBUSY ? -EBUSY : -ENODEV;
		free(m);
		return rc;
	}
	rc = open_resource(addr, bar, 0, m);
	if (!rc && flock(m->fd, LOCK_EX | LOCK_NB) < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: PCI card %s is in use by another program\n",
				addr);
		munmap((void *)m->mem, m->len);
		close(m->fd);
		rc = -EBUSY;
	}
	if (rc) {
		free(m);
		return rc;
	}
	*map = m;
	return 0;
}

void rtapi_pci_unmap_bar(struct rtapi_pci_bar *m)
{
	if (m->sim >= 0) {
		if (m->own)
			rtapi_pcisim_release(m->sim);
	} else {
		if (m->mem)
			munmap((void *)m->mem, m->len);
		close(m->fd);
	}
	free(m);
}

/* size 4 or 1: a simulated card, the mapped memory, or pread/pwrite on an I/O BAR */
static rtapi_u32 bar_read(struct rtapi_pci_bar *m, unsigned long offset, int size)
{
	rtapi_u32 v = 0;

	if (m->sim >= 0)
		return rtapi_pcisim_read(m->sim, m->bar, offset, size);
	if (offset + size > m->len)
		return size == 4 ? ~0u : 0xff;
	if (m->mem)
		return size == 4 ? *(volatile rtapi_u32 *)(m->mem + offset) : m->mem[offset];
	if (pread(m->fd, &v, size, (off_t)offset) != size)
		return size == 4 ? ~0u : 0xff;
	return v;	/* little-endian: a byte lands in the low bits */
}

static void bar_write(struct rtapi_pci_bar *m, unsigned long offset, int size, rtapi_u32 value)
{
	rtapi_u8 b = (rtapi_u8)value;

	if (m->sim >= 0)
		rtapi_pcisim_write(m->sim, m->bar, offset, size, value);
	else if (offset + size > m->len)
		return;
	else if (m->mem && size == 4)
		*(volatile rtapi_u32 *)(m->mem + offset) = value;
	else if (m->mem)
		m->mem[offset] = b;
	else if (pwrite(m->fd, size == 4 ? (void *)&value : (void *)&b, size, (off_t)offset) != size)
		return;		/* the card is gone: nothing to do in a realtime path */
}

rtapi_u32 rtapi_pci_readl(struct rtapi_pci_bar *m, unsigned long offset)
{
	return bar_read(m, offset, 4);
}

void rtapi_pci_writel(struct rtapi_pci_bar *m, unsigned long offset, rtapi_u32 value)
{
	bar_write(m, offset, 4, value);
}

rtapi_u8 rtapi_pci_readb(struct rtapi_pci_bar *m, unsigned long offset)
{
	return (rtapi_u8)bar_read(m, offset, 1);
}

void rtapi_pci_writeb(struct rtapi_pci_bar *m, unsigned long offset, rtapi_u8 value)
{
	bar_write(m, offset, 1, value);
}

/* --- drivers --- */

static int id_matches(const struct rtapi_pci_id *ids, const char *d)
{
	unsigned int v = read_hex(d, "vendor"), dev = read_hex(d, "device");
	unsigned int sv = read_hex(d, "subsystem_vendor"), sd = read_hex(d, "subsystem_device");
	int k;

	for (k = 0; ids[k].vendor; k++)
		if (ids[k].vendor == v && ids[k].device == dev && ids[k].subvendor == sv &&
		    ids[k].subdevice == sd)
			return k;
	return -1;
}

static int add_dev(struct pci_glue *g, struct rtapi_pci_driver *drv, struct rtapi_pci_dev *d,
		   int which)
{
	int rc = g->n < MAX_DEVS ? drv->probe(d, &drv->ids[which]) : 1;

	if (rc == 0)
		g->dev[g->n++] = d;
	return rc;
}

static void free_dev(struct rtapi_pci_dev *d)
{
	if (d->sim >= 0)
		rtapi_pcisim_release(d->sim);
	if (d->lock_fd >= 0)
		close(d->lock_fd);
	free(d);
}

static struct rtapi_pci_dev *new_dev(void)
{
	struct rtapi_pci_dev *d = calloc(1, sizeof(*d));

	if (d) {
		d->sim = -1;
		d->lock_fd = -1;
	}
	return d;
}

static int probe_sim(struct pci_glue *g, struct rtapi_pci_driver *drv)
{
	int h = -1, which, rc;

	while ((h = rtapi_pcisim_claim_match(drv->ids, h + 1, drv->name, &which)) >= 0) {
		struct rtapi_pci_dev *d = new_dev();

		if (!d) {
			rtapi_pcisim_release(h);
			return -ENOMEM;
		}
		d->sim = h;
		snprintf(d->name, sizeof(d->name), "sim:%s", rtapi_pcisim_name(h));
		rc = add_dev(g, drv, d, which);
		if (rc)
			free_dev(d);
		if (rc < 0)
			return rc;
	}
	return 0;
}

/* a real card: locked through its config file, enabled (root), then probed */
static int probe_real(struct pci_glue *g, struct rtapi_pci_driver *drv, const char *addr,
		      int which)
{
	struct rtapi_pci_dev *d = new_dev();
	char path[512];
	int fd, rc;

	if (!d)
		return -ENOMEM;
	snprintf(d->addr, sizeof(d->addr), "%s", addr);
	snprintf(d->name, sizeof(d->name), "%s", addr);
	snprintf(path, sizeof(path), "%s/%s/config", sys_pci(), addr);
	d->lock_fd = open(path, O_RDONLY | O_CLOEXEC);
	if (d->lock_fd < 0 || flock(d->lock_fd, LOCK_EX | LOCK_NB) < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: PCI card %s is in use by another program\n", addr);
		free_dev(d);
		return -EBUSY;
	}
	snprintf(path, sizeof(path), "%s/%s/enable", sys_pci(), addr);
	fd = open(path, O_WRONLY | O_CLOEXEC);
	if (fd >= 0) {		/* without root the BAR mapping says what is missing */
		ssize_t w = write(fd, "1", 1);

		(void)w;
		close(fd);
	}
	rc = add_dev(g, drv, d, which);
	if (rc)
		free_dev(d);
	return rc;
}

int rtapi_pci_register_driver(struct rtapi_pci_driver *drv)
{
	struct pci_glue *g = calloc(1, sizeof(*g));
	struct dirent **list;
	int n, i, which, rc;

	if (!g)
		return -ENOMEM;
	drv->rtapi = g;
	rc = probe_sim(g, drv);
	n = scandir(sys_pci(), &list, 0, by_name);
	for (i = 0; i < n; i++) {
		if (!rc && list[i]->d_name[0] != '.' && (which = id_matches(drv->ids, list[i]->d_name)) >= 0)
			rc = probe_real(g, drv, list[i]->d_name, which);
		free(list[i]);
	}
	if (n >= 0)
		free(list);
	if (rc < 0) {
		rtapi_pci_unregister_driver(drv);
		return rc;
	}
	return g->n;
}

void rtapi_pci_unregister_driver(struct rtapi_pci_driver *drv)
{
	struct pci_glue *g = drv->rtapi;

	if (!g)
		return;
	while (g->n > 0) {
		struct rtapi_pci_dev *d = g->dev[--g->n];

		drv->remove(d);
		free_dev(d);
	}
	free(g);
	drv->rtapi = 0;
}

/* 1 when BAR 'bar' of the card is I/O space (the resource file's flags) */
static int bar_is_io(const char *addr, int bar)
{
	char path[512];
	unsigned long long start, end, flags = 0;
	FILE *f;
	int i, io = 0;

	snprintf(path, sizeof(path), "%s/%s/resource", sys_pci(), addr);
	f = fopen(path, "r");
	if (!f)
		return 0;
	for (i = 0; i <= bar; i++)
		if (fscanf(f, "%llx %llx %llx", &start, &end, &flags) != 3)
			flags = 0;
	io = (flags & 0x100) != 0;	/* IORESOURCE_IO */
	fclose(f);
	return io;
}

int rtapi_pci_dev_map_bar(struct rtapi_pci_dev *d, int bar, struct rtapi_pci_bar **map)
{
	struct rtapi_pci_bar *m = calloc(1, sizeof(*m));
	int rc;

	if (!m)
		return -ENOMEM;
	m->bar = bar;
	m->sim = d->sim;
	m->fd = -1;
	if (d->sim >= 0) {
		m->len = rtapi_pcisim_bar_len(d->sim, bar);
		if (!m->len) {
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: PCI card %s has no BAR%d\n", d->name, bar);
			free(m);
			return -EIO;
		}
		*map = m;
		return 0;
	}
	rc = open_resource(d->addr, bar, bar_is_io(d->addr, bar), m);
	if (rc) {
		free(m);
		return rc;
	}
	*map = m;
	return 0;
}

const char *rtapi_pci_dev_name(const struct rtapi_pci_dev *d)
{
	return d->name;
}

void rtapi_pci_set_drvdata(struct rtapi_pci_dev *d, void *data)
{
	d->drvdata = data;
}

void *rtapi_pci_get_drvdata(const struct rtapi_pci_dev *d)
{
	return d->drvdata;
}
