/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_pci_uspace.c - rtapi_pci.h in the simulated flavor: a simulated card if one
 * is registered, else the card's /sys/bus/pci/devices/<addr>/resourceN mapped with
 * mmap (root only) and locked with flock so that a second driver is refused. Cards
 * are taken in the sorted order of their PCI addresses, as the kernel scans them. */
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

#define SYS_PCI "/sys/bus/pci/devices"

struct rtapi_pci_bar {
	int sim;		/* simulated card's handle, or -1 */
	unsigned long len;
	volatile unsigned char *mem;
	int fd;
};

static unsigned int read_hex(const char *dev, const char *file)
{
	char path[512];
	unsigned int v = 0;
	FILE *f;

	snprintf(path, sizeof(path), SYS_PCI "/%s/%s", dev, file);
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

	n = scandir(SYS_PCI, &list, 0, by_name);
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

int rtapi_pci_map_bar(unsigned int vendor, unsigned int device, int index, int bar,
		      const char *owner, struct rtapi_pci_bar **map)
{
	struct rtapi_pci_bar *m = calloc(1, sizeof(*m));
	char addr[260], path[512];
	struct stat st;
	void *mem;
	int skipped = 0;

	if (!m)
		return -ENOMEM;
	m->sim = rtapi_pcisim_claim(vendor, device, index, owner, &skipped, &m->len);
	if (m->sim >= 0) {
		*map = m;
		return 0;
	}
	if (m->sim == -EBUSY || !find_card(vendor, device, index - skipped, addr, sizeof(addr))) {
		int rc = m->sim == -EBUSY ? -EBUSY : -ENODEV;

		free(m);
		return rc;
	}
	snprintf(path, sizeof(path), SYS_PCI "/%s/resource%d", addr, bar);
	m->fd = open(path, O_RDWR | O_SYNC);
	if (m->fd < 0 || fstat(m->fd, &st) < 0 || st.st_size <= 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: PCI card %s BAR%d: cannot open %s: %m "
				"(needs root)\n", addr, bar, path);
		if (m->fd >= 0)
			close(m->fd);
		free(m);
		return -EPERM;
	}
	if (flock(m->fd, LOCK_EX | LOCK_NB) < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: PCI card %s is in use by another program\n",
				addr);
		close(m->fd);
		free(m);
		return -EBUSY;
	}
	mem = mmap(0, st.st_size, PROT_READ | PROT_WRITE, MAP_SHARED, m->fd, 0);
	if (mem == MAP_FAILED) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: PCI card %s: cannot map BAR%d: %m\n", addr, bar);
		close(m->fd);
		free(m);
		return -EIO;
	}
	m->mem = mem;
	m->len = st.st_size;
	*map = m;
	return 0;
}

void rtapi_pci_unmap_bar(struct rtapi_pci_bar *m)
{
	if (m->sim >= 0) {
		rtapi_pcisim_release(m->sim);
	} else {
		munmap((void *)m->mem, m->len);
		close(m->fd);
	}
	free(m);
}

rtapi_u32 rtapi_pci_readl(struct rtapi_pci_bar *m, unsigned long offset)
{
	if (m->sim >= 0)
		return rtapi_pcisim_readl(m->sim, offset);
	return offset + 4 <= m->len ? *(volatile rtapi_u32 *)(m->mem + offset) : ~0u;
}

void rtapi_pci_writel(struct rtapi_pci_bar *m, unsigned long offset, rtapi_u32 value)
{
	if (m->sim >= 0)
		rtapi_pcisim_writel(m->sim, offset, value);
	else if (offset + 4 <= m->len)
		*(volatile rtapi_u32 *)(m->mem + offset) = value;
}
