/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_parport_uspace.c - the simulated flavor's access to Linux parallel ports for
 * hal_parport_get (hal_parport.h): a port is found in /proc/sys/dev/parport/parportN/
 * base-addr, claimed with PPCLAIM on /dev/parportN (held open until released), and
 * its registers granted to this process with ioperm (rtapi_request_region). */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/ioctl.h>
#include <unistd.h>
#include <linux/ppdev.h>
#include "rtapi.h"
#include "hal_parport.h"

#define MAX_LINUX_PORTS 16

struct linux_pp {
	int fd;
	unsigned short base;
};

/* base and base_hi of Linux's parportN: 1, or 0 if there is no such port. */
static int read_base(int n, unsigned int *base, unsigned int *hi)
{
	char path[64];
	FILE *f;
	int got;

	snprintf(path, sizeof(path), "/proc/sys/dev/parport/parport%d/base-addr", n);
	f = fopen(path, "r");
	if (!f)
		return 0;
	*hi = 0;
	got = fscanf(f, "%u %u", base, hi);
	fclose(f);
	return got >= 1;
}

int rtapi_parport_linux_claim(unsigned int which, int is_number, unsigned int modes,
			      const char *owner, unsigned short *base,
			      unsigned short *base_hi, void **handle)
{
	unsigned int b = 0, hi = 0;
	int n = -1, i, fd;
	char dev[32];
	struct linux_pp *pp;

	if (is_number) {
		if (read_base(which, &b, &hi))
			n = which;
	} else {
		for (i = 0; i < MAX_LINUX_PORTS && n < 0; i++)
			if (read_base(i, &b, &hi) && b == which)
				n = i;
		if (n < 0)
			return 0;
	}
	if (n < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: Linux has no parport %u "
				"(/proc/sys/dev/parport/parport%u missing; modprobe parport_pc?)\n",
				which, which);
		return -ENODEV;
	}
	snprintf(dev, sizeof(dev), "/dev/parport%d", n);
	fd = open(dev, O_RDWR);
	if (fd < 0 || ioctl(fd, PPEXCL) < 0 || ioctl(fd, PPCLAIM) < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: cannot claim %s (port 0x%x): %m\n",
				dev, b);
		if (fd >= 0)
			close(fd);
		return -EBUSY;
	}
	if (!rtapi_request_region(b, 8, owner)) {
		close(fd);
		return -EPERM;
	}
	pp = malloc(sizeof(*pp));
	if (!pp) {
		rtapi_release_region(b, 8);
		close(fd);
		return -ENOMEM;
	}
	pp->fd = fd;
	pp->base = b;
	*base = b;
	*base_hi = hi;
	*handle = pp;
	(void)modes;	/* ppdev does not report the modes; nothing to warn about */
	return 1;
}

void rtapi_parport_linux_release(void *handle)
{
	struct linux_pp *pp = handle;

	rtapi_release_region(pp->base, 8);
	ioctl(pp->fd, PPRELEASE);
	close(pp->fd);
	free(pp);
}
